"""A policy's episode as a bundle: the scenario's files plus the run files the simulation writes.

    scenario.yaml      the scenario, its robot path replaced by the path the policy drove
                       (so `grove simulate` and the app's "robot follows its path" drive it again)
    trees/, fields/, grid.npz, generation.json   as in the source bundle (hard links where possible)
    trajectories.csv   every simulation step, robot id 0 (the existing TrajectoryRecorder writer); the
                       robot's yaw is the simulator's, its direction of motion (a unicycle turning on
                       the spot keeps its last one there)
    events.jsonl       queue joins and services, evacuations, goals (scenario.events.write_events)
    metrics.json       HuNavSim robot metrics and crowd metrics (analysis.bundle_metrics)
    episode.json       kinematics, control period, actions, return, outcome: enough to replay the
                       policy's commands in the environment

`grove metrics`, `grove picture`, `grove export trajectories|rosbag|foxglove` read it as any bundle.
"""

from __future__ import annotations

import dataclasses
import json
import os
from pathlib import Path
from typing import Any

import numpy as np

from grove_tui.analysis.bundle_metrics import bundle_metrics
from grove_tui.files import absolute_path, atomic_directory, link_or_copy
from grove_tui.scenario.bundle import RUN_FILES, SCENARIO_FILE, WHAT, is_bundle
from grove_tui.scenario.events import write_events

EPISODE_FILE = "episode.json"
# The driven path keeps a point every this many metres (plus the last): `grove simulate` walks it
# at the robot's top speed, so more points would only slow the follower's waypoint switching.
PATH_SPACING = 0.25


def driven_path(xy: np.ndarray, spacing: float = PATH_SPACING) -> tuple[tuple[float, float], ...]:
    """The robot's positions thinned to one every `spacing` metres along the way, first and last kept."""
    points = [xy[0]]
    for p in xy[1:]:
        if np.hypot(*(p - points[-1])) >= spacing:
            points.append(p)
    if len(xy) > 1 and np.hypot(*(xy[-1] - points[-1])) > 1e-9:
        points.append(xy[-1])
    return tuple((round(float(p[0]), 4), round(float(p[1]), 4)) for p in points)


# env: Any, the SocialNavEnv (env.py imports this module, lazily)
def record_episode(env: Any, out_dir: str | os.PathLike[str], overwrite: bool = False) -> Path:
    """Write `env`'s current episode (a SocialNavEnv after reset) as a bundle at `out_dir`, atomically."""
    source: Path = env.current.bundle_dir
    sim = env.sim
    history = env.history
    xy = history.robot[: history.size, :2]
    robot = dataclasses.replace(env.current.scenario.robot, path=driven_path(xy))
    scenario = dataclasses.replace(env.current.scenario, robot=robot)
    episode = {
        "source_bundle": str(source),
        "kinematics": env.kinematics,
        "control_period": env.control_period,
        "sim_dt": env.sim_dt,
        "steps": env.episode_steps,
        "seconds": round(float(sim.time), 4),
        "outcome": env.outcome or "running",
        "return": env.episode_return,
        "actions": [list(a) for a in env.episode_actions],
    }
    target = absolute_path(out_dir)
    with atomic_directory(target, owned=is_bundle, what=WHAT, overwrite=overwrite) as stage:
        for path in sorted(source.rglob("*")):
            rel = path.relative_to(source)
            if str(rel) in RUN_FILES or str(rel) in (SCENARIO_FILE, EPISODE_FILE) or path.is_symlink() \
                    or not path.is_file():
                continue
            link_or_copy(path, stage / rel)
        (stage / SCENARIO_FILE).write_text(scenario.dump_yaml(), encoding="utf-8")
        (stage / EPISODE_FILE).write_text(json.dumps(episode, indent=1) + "\n", encoding="utf-8")
        sim.recorder.write_csv(stage / "trajectories.csv")
        write_events(stage / "events.jsonl", sim.events)
        bundle_metrics(stage)
    return target
