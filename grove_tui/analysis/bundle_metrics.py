"""Metrics of a simulated bundle, from its trajectories, events, world and scenario; kept in metrics.json."""

from __future__ import annotations

import json
from pathlib import Path

from grove_tui.files import write_text_atomic
from grove_tui.analysis.metrics import MetricsReport, Trajectories, compute_metrics
from grove_tui.scenario.events import read_events
from grove_tui.scenario.model import Scenario
from grove_tui.world import load_world

TRAJECTORIES = "trajectories.csv"
EVENTS = "events.jsonl"
METRICS = "metrics.json"


def bundle_metrics(bundle_dir: str | Path, write: bool = True) -> tuple[MetricsReport, Path]:
    bundle = Path(bundle_dir)
    scenario = Scenario.load(bundle / "scenario.yaml")
    world = load_world(scenario.world)
    traj = Trajectories.from_csv(bundle / TRAJECTORIES)
    events_path = bundle / EVENTS
    events = read_events(events_path) if events_path.exists() else []
    robot = scenario.robot
    radii = {a.radius for a in scenario.agents}
    report = compute_metrics(
        traj,
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
    # HuNavSim 2.0's danger and surprise costs, beside the 1.0 set (analysis/hunav2_metrics.py); the
    # line of sight runs over the map HuNavSim's evaluator gets, the grid without inflation.
    from grove_tui.analysis.hunav2_metrics import hunav2_costs
    from grove_tui.navigation.grid import build_grid

    report.robot.update(hunav2_costs(traj, build_grid(world, scenario.resolution, inflation=0.0),
                                     robot_radius=0.3 if robot is None else robot.radius,
                                     person_radius=max(radii) if radii else 0.35))
    path = bundle / METRICS
    if write:
        write_text_atomic(path, json.dumps(report.to_dict(), indent=2, sort_keys=True) + "\n")
    return report, path
