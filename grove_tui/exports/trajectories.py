"""Trajectories of a simulated bundle in the forms crowd researchers load: our CSV, JuPedSim's sqlite
schema with the walkable area (PedPy's `load_trajectory_from_jupedsim_sqlite`), and PedPy's text format."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np

from grove_tui.errors import TrajectoryExportError
from grove_tui.analysis.metrics import Trajectories
from grove_tui.crowd.recording import TrajectoryRecorder
from grove_tui.scenario.bundle import load_bundle_world, load_scenario


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


def export_trajectories(bundle_dir: str | Path, out_dir: str | Path) -> list[Path]:
    bundle = Path(bundle_dir)
    csv = bundle / "trajectories.csv"
    if not csv.exists():
        raise TrajectoryExportError(f"{csv}: no trajectories yet; simulate first (grove simulate {bundle})")
    scenario = load_scenario(bundle)
    world = load_bundle_world(bundle, scenario)
    # Read (and check) the trajectories before creating anything: a broken CSV leaves no folder behind.
    recorder = recorder_from_csv(csv)
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    try:
        written = [
            recorder.write_jupedsim_sqlite(out / "trajectories.sqlite", world.walkable().wkt),
            recorder.write_pedpy_txt(out / "trajectories.txt"),
        ]
    finally:
        recorder.close()
    target = out / "trajectories.csv"
    if target.resolve() != csv.resolve():
        shutil.copy2(csv, target)
    return [target, *written]
