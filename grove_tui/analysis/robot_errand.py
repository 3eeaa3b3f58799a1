"""Checks of the robot's errand on a run (generation/robot_errand.py claims them).

robot_pickup: the robot stood still (under STOP_SPEED) at the pick-up place for the claim's seconds in one
go. robot_dropoff: it got to the drop-off place after that stop (after the run's start when nothing is
picked up) and stood there the claim's seconds. Both measured on the robot's sampled frames.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

STOP_SPEED = 0.05  # m/s: standing still

# (F, 2) robot positions -> (F,) at the place
AtPlace = Callable[[np.ndarray], np.ndarray]


class StopTrack:
    """The first stop of `seconds` standing still at a place, from `after` on."""

    def __init__(self, at: AtPlace, seconds: float, sample_dt: float) -> None:
        self.at = at
        self.seconds = float(seconds)
        self.dt = float(sample_dt)
        self.run_from = math.nan  # when the current stay there began
        self.arrived = math.inf  # first time at the place (counted from `after`)
        self.done = math.inf  # when the stop had lasted `seconds`
        self.longest = 0.0

    def add(self, t: np.ndarray, robot: np.ndarray, speed: np.ndarray, after: float = 0.0) -> None:
        there = self.at(robot[:, :2]) & (t >= after - 1e-9)
        still = there & (speed <= STOP_SPEED)
        for k in range(t.size):
            if there[k] and math.isinf(self.arrived):
                self.arrived = float(t[k])
            if not math.isinf(self.done):
                return
            if still[k]:
                if math.isnan(self.run_from):
                    self.run_from = float(t[k])
                held = float(t[k]) - self.run_from + self.dt
                self.longest = max(self.longest, held)
                if held + 1e-6 >= self.seconds:
                    self.done = float(t[k])
            else:
                self.run_from = math.nan


def speeds(robot: np.ndarray, robot_vel: np.ndarray | None, t: np.ndarray) -> np.ndarray:
    if robot_vel is not None:
        return np.hypot(robot_vel[:, 0], robot_vel[:, 1])
    if t.size < 2:
        return np.zeros(t.size)
    step = np.hypot(np.diff(robot[:, 0]), np.diff(robot[:, 1])) / np.maximum(np.diff(t), 1e-6)
    return np.concatenate([step[:1], step])


def pickup_verdict(track: StopTrack, where: str) -> tuple[bool, str]:
    if math.isinf(track.arrived):
        return False, f"never got to {where}"
    if math.isinf(track.done):
        return False, (f"got to {where} at t = {track.arrived:.1f} s but never stood there {track.seconds:g} s "
                       f"(longest {track.longest:.1f} s)")
    return True, f"stood at {where} {track.seconds:g} s, until t = {track.done:.1f} s"


def dropoff_verdict(track: StopTrack, where: str, pickup_done: float | None, pickup_where: str | None) -> tuple[bool, str]:
    if pickup_done is not None and math.isinf(pickup_done):
        return False, f"never picked up at {pickup_where}, so nothing was brought to {where}"
    if math.isinf(track.arrived):
        after = f" after the stop at {pickup_where}" if pickup_done is not None else ""
        return False, f"never got to {where}{after}"
    if math.isinf(track.done):
        return False, f"got to {where} at t = {track.arrived:.1f} s but did not stand there {track.seconds:g} s"
    after = f" after leaving {pickup_where} (t = {pickup_done:.1f} s)" if pickup_done is not None else ""
    return True, f"got to {where} at t = {track.arrived:.1f} s{after} and stood there"
