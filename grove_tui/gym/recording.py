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
from typing import TYPE_CHECKING

import numpy as np

from grove_tui.scenario.bundle import EPISODE_FILE
from grove_tui.services.session import GroveSession

if TYPE_CHECKING:
    from grove_tui.gym.env import SocialNavEnv  # env.py imports this module lazily

__all__ = ["EPISODE_FILE", "PATH_SPACING", "driven_path", "record_episode"]

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


def record_episode(env: SocialNavEnv, out_dir: str | os.PathLike[str], overwrite: bool = False) -> Path:
    """Write `env`'s current episode (a SocialNavEnv after reset) as a bundle at `out_dir`, atomically."""
    loaded = env.loaded
    source: Path = loaded.bundle_dir
    sim = env.running
    history = env.history
    xy = history.robot[: history.size, :2]
    robot = dataclasses.replace(loaded.robot, path=driven_path(xy))
    scenario = dataclasses.replace(loaded.scenario, robot=robot)
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
    # The services layer writes it, as every bundle (scenario.bundle.derive_bundle: atomic, guarded).
    return GroveSession().record_episode(source, out_dir, scenario, episode, sim, overwrite=overwrite)
