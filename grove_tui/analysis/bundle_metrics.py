"""Metrics of a simulated bundle, from its trajectories, events, world and scenario; kept in metrics.json."""

from __future__ import annotations

import json
import os
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from grove_tui.files import check_output_file, write_text_atomic
from grove_tui.analysis.metrics import (MetricsReport, Trajectories, compute_metrics, compute_metrics_csv,
                                        iter_trajectory_chunks)
from grove_tui.scenario.events import read_events
from grove_tui.errors import MetricsError
from grove_tui.scenario.bundle import MAX_TRAJECTORY_BYTES, bundle_member, load_bundle_world, load_scenario
from grove_tui.scenario.events import MAX_EVENTS_BYTES
from grove_tui.scenario.model import Scenario

TRAJECTORIES = "trajectories.csv"
EVENTS = "events.jsonl"
METRICS = "metrics.json"


def bundle_metrics(bundle_dir: str | Path, write: bool = True) -> tuple[MetricsReport, Path]:
    """The run's metrics, kept in the bundle's metrics.json (`write`).

    The run files are read only as regular files inside the bundle, of bounded size (a link to
    /dev/zero or a pipe is refused before it is opened); metrics.json is replaced atomically and
    never through a link (a link there is refused: it could point at any file).
    """
    bundle = Path(bundle_dir)
    scenario = load_scenario(bundle)
    world = load_bundle_world(bundle, scenario)
    path = bundle / METRICS
    if write:  # before the work: a refused output costs nothing
        check_output_file(path, **_METRICS_GUARD, own_folder=bundle)
    if not os.path.lexists(bundle / TRAJECTORIES):
        raise MetricsError(f"{bundle / TRAJECTORIES}: no trajectory file (simulate the bundle first)")
    trajectories = bundle_member(bundle, TRAJECTORIES, "trajectory file", MAX_TRAJECTORY_BYTES)
    events = (read_events(bundle_member(bundle, EVENTS, "event log", MAX_EVENTS_BYTES))
              if os.path.lexists(bundle / EVENTS) else [])
    # Streamed a block of frames at a time: a long run's CSV is never held in memory whole.
    report = compute_metrics_csv(trajectories, **metrics_options(scenario, world, events))
    ids, _groups, chunks = iter_trajectory_chunks(trajectories)
    accumulator = _hunav2_accumulator(scenario, world, len(ids))
    for chunk in chunks:
        accumulator.add(chunk)
    report.robot.update(accumulator.result())
    if write:
        write_text_atomic(path, json.dumps(report.to_dict(), indent=2, sort_keys=True) + "\n", **_METRICS_GUARD,
                          own_folder=bundle)
    return report, path


# metrics.json is the bundle's own file: any regular file there is replaced, a link or a folder never.
_METRICS_GUARD: dict = dict(owned=lambda _path: True, what="metrics file")


def scenario_metrics(scenario: Scenario, world: Any, traj: Trajectories, events: Sequence[Any]) -> MetricsReport:
    """metrics.json's report of a run held in memory: what the app's live counters show, so both always agree."""
    report = compute_metrics(traj, **metrics_options(scenario, world, events))
    accumulator = _hunav2_accumulator(scenario, world, traj.ids.size)
    accumulator.add(traj)
    report.robot.update(accumulator.result())
    return report


def _hunav2_accumulator(scenario: Scenario, world: Any, people: int):
    """HuNavSim 2.0's danger and surprise costs, beside the 1.0 set (analysis/hunav2_metrics.py); the line
    of sight runs over the map HuNavSim's evaluator gets, the grid without inflation."""
    from grove_tui.analysis.hunav2_metrics import Hunav2Accumulator
    from grove_tui.navigation.grid import build_grid

    radii = {a.radius for a in scenario.agents}
    return Hunav2Accumulator(people, build_grid(world, scenario.resolution, inflation=0.0),
                             robot_radius=0.3 if scenario.robot is None else scenario.robot.radius,
                             person_radius=max(radii) if radii else 0.35)


def metrics_options(scenario: Scenario, world: Any, events: Sequence[Any]) -> dict[str, Any]:
    """The scenario's side of the metrics: the same for the file on disk and the live run."""
    robot = scenario.robot
    radii = {a.radius for a in scenario.agents}
    return dict(
        walls=world.walls(),
        robot_goal=None if robot is None else robot.goal,
        robot_radius=0.3 if robot is None else robot.radius,
        person_radius=max(radii) if radii else 0.35,
        final_goals={a.id: a.goals[-1] for a in scenario.agents if a.goals},
        events=events,
        walkable_area=float(world.walkable().area),
        # The scenario's groups, not the recorded column: behaviours change the SFM group while they
        # run (a conversation drops it, JoinGroup renumbers it); HuNavSim's group_id is the configured one.
        groups={a.id: a.group for a in scenario.agents},
    )
