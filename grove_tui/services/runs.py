"""The runs folder: where a generation asked for without an output folder (the app's) writes its bundle,
named by time, prompt and seed, and how the recent-runs list reads it back. Also what each warm-up step
took on this machine last time (the ETA of the loading the app shows), kept in the data dir."""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from pathlib import Path

from grove_tui.errors import GroveError
from grove_tui.settings import data_dir

STEP_SECONDS_FILE = "warm_up_seconds.json"


@dataclass(frozen=True)
class RunInfo:
    """One saved bundle in the runs folder, as the recent-runs list shows it."""

    path: Path
    modified: float  # seconds since the epoch, of scenario.yaml
    prompt: str = ""
    world: str = ""
    preset: str = ""
    seed: int = 0
    agents: int = 0
    simulated: bool = False
    error: str = ""  # why the bundle cannot be opened; empty when it can


def list_runs(runs_dir: Path, limit: int = 50) -> list[RunInfo]:
    """The newest `limit` bundles directly under `runs_dir` (a missing folder is an empty list)."""
    from grove_tui.scenario.bundle import SCENARIO_FILE, is_bundle
    from grove_tui.scenario.model import Scenario

    if not runs_dir.is_dir():
        return []
    bundles = [path for path in runs_dir.iterdir() if path.is_dir() and is_bundle(path)]
    bundles.sort(key=lambda path: (path / SCENARIO_FILE).stat().st_mtime, reverse=True)
    runs = []
    for path in bundles[:limit]:
        modified = (path / SCENARIO_FILE).stat().st_mtime
        try:
            scenario = Scenario.load(path / SCENARIO_FILE)
        except (GroveError, OSError) as exc:  # a broken scenario.yaml, or a file that vanished meanwhile
            runs.append(RunInfo(path, modified, error=str(exc)))
            continue
        runs.append(RunInfo(path, modified, scenario.prompt, scenario.world, scenario.preset, int(scenario.seed),
                            len(scenario.agents), (path / "trajectories.csv").is_file()))
    return runs


def slug(text: str, limit: int = 40) -> str:
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-")[:limit] or "scenario"


def free_folder(root: Path, name: str) -> Path:
    """`root/name`, or `root/name-2`, `-3`... the first that does not exist yet."""
    out, suffix = root / name, 1
    while out.exists():
        suffix += 1
        out = root / f"{name}-{suffix}"
    return out


def load_step_seconds() -> dict[str, float]:
    """Seconds each warm-up step took last time on this machine (data dir); {} before the first warm-up."""
    try:
        data = json.loads((data_dir() / STEP_SECONDS_FILE).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    if not isinstance(data, dict):
        return {}
    return {str(k): float(v) for k, v in data.items() if isinstance(v, (int, float)) and 0 <= v < 3600}


def save_step_seconds(seconds: dict[str, float]) -> None:
    from grove_tui.files import write_text_atomic

    if not seconds:
        return
    path = data_dir() / STEP_SECONDS_FILE
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        write_text_atomic(path, json.dumps(dict(sorted(seconds.items())), indent=2) + "\n")
    except OSError:
        pass  # an ETA is a nicety: a read-only data dir must not fail a generation
