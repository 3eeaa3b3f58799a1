"""Metrics of a simulated bundle, from its trajectories, events, world and scenario; kept in metrics.json."""

from __future__ import annotations

import json
import os
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, TypedDict

import numpy as np

from grove_tui.files import check_output_file, write_text_atomic
from grove_tui.analysis.metrics import (MetricsReport, Trajectories, compute_metrics, compute_metrics_csv,
                                        iter_trajectory_chunks)
from grove_tui.analysis.outcomes import GROUNDING_FILE
from grove_tui.scenario.events import SimEvent, read_events
from grove_tui.errors import MetricsError
from grove_tui.scenario.bundle import MAX_TRAJECTORY_BYTES, bundle_member, load_bundle_world, load_scenario
from grove_tui.scenario.events import MAX_EVENTS_BYTES
from grove_tui.scenario.model import Scenario

if TYPE_CHECKING:
    from grove_tui.analysis.hunav2_metrics import Hunav2Accumulator
    from grove_tui.analysis.outcomes import OutcomeChecker
    from grove_tui.world.model import World

TRAJECTORIES = "trajectories.csv"
EVENTS = "events.jsonl"
METRICS = "metrics.json"


def bundle_metrics(bundle_dir: str | Path, write: bool = True, outcomes: bool = False) -> tuple[MetricsReport, Path]:
    """The run's metrics, kept in the bundle's metrics.json (`write`). With `outcomes`, the grounding
    report's claims are checked on the same pass over the trajectories (analysis/outcomes.py) and
    kept as grounding.json (when the bundle has a planned report).

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
        if outcomes:
            check_output_file(bundle / GROUNDING_FILE, **_GROUNDING_GUARD, own_folder=bundle)
    if not os.path.lexists(bundle / TRAJECTORIES):
        raise MetricsError(f"{bundle / TRAJECTORIES}: no trajectory file (simulate the bundle first)")
    trajectories = bundle_member(bundle, TRAJECTORIES, "trajectory file", MAX_TRAJECTORY_BYTES)
    events = (read_events(bundle_member(bundle, EVENTS, "event log", MAX_EVENTS_BYTES))
              if os.path.lexists(bundle / EVENTS) else [])
    # Streamed a block of frames at a time: a long run's CSV is never held in memory whole.
    report = compute_metrics_csv(trajectories, **metrics_options(scenario, world, events))
    ids, _groups, chunks = iter_trajectory_chunks(trajectories)
    accumulator = _hunav2_accumulator(scenario, world, len(ids))
    checker = _outcome_checker(bundle, scenario, world, ids) if outcomes else None
    for chunk in chunks:
        accumulator.add(chunk)
        if checker is not None:
            checker.add(chunk)
    report.robot.update(accumulator.result())
    if write:
        write_text_atomic(path, json.dumps(report.to_dict(), indent=2, sort_keys=True) + "\n", **_METRICS_GUARD,
                          own_folder=bundle)
        if checker is not None:
            checked = checker.result(events)
            write_text_atomic(bundle / GROUNDING_FILE, json.dumps(checked.to_dict(), indent=2, ensure_ascii=False)
                              + "\n", **_GROUNDING_GUARD, own_folder=bundle)
    return report, path


# metrics.json is the bundle's own file: any regular file there is replaced, a link or a folder never.
_METRICS_GUARD: dict = dict(owned=lambda _path: True, what="metrics file")
_GROUNDING_GUARD: dict = dict(owned=lambda _path: True, what="checked grounding report")


def _outcome_checker(bundle: Path, scenario: Scenario, world: World, ids: np.ndarray) -> OutcomeChecker | None:
    from grove_tui.analysis.outcomes import OutcomeChecker, planned_report
    from grove_tui.scenario.bundle import REPORT_FILE, load_report

    planned = planned_report(load_report(bundle)) if (bundle / REPORT_FILE).is_file() else None
    if planned is None:
        return None
    checker = OutcomeChecker(planned, scenario, world)
    checker.set_ids(ids)
    return checker


def scenario_metrics(scenario: Scenario, world: World, traj: Trajectories, events: Sequence[SimEvent]) -> MetricsReport:
    """metrics.json's report of a run held in memory: what the app's live counters show, so both always agree."""
    report = compute_metrics(traj, **metrics_options(scenario, world, events))
    accumulator = _hunav2_accumulator(scenario, world, traj.ids.size)
    accumulator.add(traj)
    report.robot.update(accumulator.result())
    return report


def _hunav2_accumulator(scenario: Scenario, world: World, people: int) -> Hunav2Accumulator:
    """HuNavSim 2.0's danger and surprise costs, beside the 1.0 set (analysis/hunav2_metrics.py); the line
    of sight runs over the map HuNavSim's evaluator gets, the grid without inflation."""
    from grove_tui.analysis.hunav2_metrics import Hunav2Accumulator
    from grove_tui.analysis.outcomes import OutcomeChecker
    from grove_tui.navigation.grid import build_grid

    radii = {a.radius for a in scenario.agents}
    return Hunav2Accumulator(people, build_grid(world, scenario.resolution, inflation=0.0),
                             robot_radius=0.3 if scenario.robot is None else scenario.robot.radius,
                             person_radius=max(radii) if radii else 0.35)


class MetricsOptions(TypedDict):
    """compute_metrics' keyword arguments that come from the scenario and the world, not the trajectories."""

    walls: np.ndarray
    robot_goal: tuple[float, float] | None
    robot_radius: float
    person_radius: float
    final_goals: Mapping[int, tuple[float, float]]
    events: Sequence[SimEvent]
    walkable_area: float
    groups: Mapping[int, int]


def metrics_options(scenario: Scenario, world: World, events: Sequence[SimEvent]) -> MetricsOptions:
    """The scenario's side of the metrics: the same for the file on disk and the live run."""
    robot = scenario.robot
    radii = {a.radius for a in scenario.agents}
    return MetricsOptions(
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
