"""Trajectories of a simulated bundle in the forms crowd researchers load: our CSV, JuPedSim's sqlite
schema with the walkable area (PedPy's `load_trajectory_from_jupedsim_sqlite`), and PedPy's text format."""

from __future__ import annotations

import os
import shutil
import sqlite3
from pathlib import Path

import numpy as np

from grove_tui.errors import OutputError, TrajectoryExportError
from grove_tui.analysis.metrics import Trajectories
from grove_tui.crowd.recording import TrajectoryRecorder
from grove_tui.files import atomic_directory, check_output_dir, refuse_overlap
from grove_tui.scenario.bundle import MAX_TRAJECTORY_BYTES, bundle_member, load_bundle_world, load_scenario

EXPORT_MARKER = ".grove-trajectories-export"


def recorder_from_csv(path: Path) -> TrajectoryRecorder:
    """Replay a trajectories.csv into a recorder, so every writer works on simulated bundles."""
    traj = Trajectories.from_csv(path)  # validates the header and numbers, names the file
    rows = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    frames = np.unique(rows[:, 0])
    dt = np.diff(np.unique(traj.t))
    fps = 1.0 / float(np.median(dt)) if dt.size else 1.0
    recorder = TrajectoryRecorder(fps, spill=True)
    order = np.argsort(rows[:, 0], kind="stable")
    rows = rows[order]
    bounds = np.searchsorted(rows[:, 0], frames, side="left").tolist() + [rows.shape[0]]
    for k in range(frames.size):
        chunk = rows[bounds[k]:bounds[k + 1]]
        recorder.record_frame(float(chunk[0, 1]), chunk[:, 2].astype(np.int64), chunk[:, 3], chunk[:, 4],
                              chunk[:, 5], chunk[:, 6], chunk[:, 7], chunk[:, 8].astype(np.int64))
    return recorder


def is_trajectories_export(path: Path) -> bool:
    """A folder `grove export trajectories` wrote (its marker file), the only kind it replaces unasked."""
    return (path / EXPORT_MARKER).is_file()


def export_trajectories(bundle_dir: str | Path, out_dir: str | Path, *, overwrite: bool = False) -> list[Path]:
    """trajectories.csv, .sqlite (JuPedSim, with the walkable area) and .txt (PedPy) in the folder `out_dir`.

    The folder is written as one: new, empty or an earlier trajectories export is replaced in one
    rename; another folder only with `overwrite`; never the bundle itself or a folder holding it.
    """
    bundle = Path(bundle_dir)
    out = check_output_dir(out_dir, **_guard(overwrite))
    refuse_overlap(out, bundle, "the bundle being exported")
    csv = bundle / "trajectories.csv"
    if not os.path.lexists(csv):
        raise TrajectoryExportError(f"{csv}: no trajectories yet; simulate first (grove simulate {bundle})")
    csv = bundle_member(bundle, "trajectories.csv", "trajectory file", MAX_TRAJECTORY_BYTES)
    scenario = load_scenario(bundle)
    world = load_bundle_world(bundle, scenario)
    # Read (and check) the trajectories before creating anything: a broken CSV leaves no folder behind.
    recorder = recorder_from_csv(csv)
    try:
        with atomic_directory(out, **_guard(overwrite)) as stage:
            recorder.write_jupedsim_sqlite(stage / "trajectories.sqlite", world.walkable().wkt)
            recorder.write_pedpy_txt(stage / "trajectories.txt")
            shutil.copyfile(csv, stage / "trajectories.csv")
            (stage / EXPORT_MARKER).write_text("written by grove export trajectories\n", encoding="utf-8")
    except sqlite3.Error as exc:  # "database or disk is full" and the like, from the JuPedSim file
        raise OutputError(f"{out}: cannot write trajectories.sqlite: {exc}") from None
    finally:
        recorder.close()
    return [out / "trajectories.csv", out / "trajectories.sqlite", out / "trajectories.txt"]


def _guard(overwrite: bool) -> dict:
    return dict(owned=is_trajectories_export, what="GROVE trajectories export", overwrite=overwrite)
