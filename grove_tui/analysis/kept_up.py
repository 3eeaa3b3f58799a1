"""Whether people kept up with the robot they follow or that escorts them ("the robot escorts a family of
four from security to gate B1", "three visitors follow the robot to the lifts").

What a researcher means by it is not "within 3 m of the robot": people keep a walking distance from a
moving robot, and a group walks behind one another, so its nearest member is a little way back and the
rest further. Two figures say it:

- the distance behind: the nearest member within `follow_distance(base, n)` of the robot while it drives
  (the base, 3 m, stretched by FILE_GAP for each member after the first: a family of four 3.4-4.8 m
  behind its escort keeps up), the others with them (the column rule of outcomes._along_the_chain);
- the arrival with it: once the robot is at its goal, the group there too within ARRIVE_WITH seconds
  (a family 6 s behind arrived with it; one that turns up a minute later did not keep up).
"""

from __future__ import annotations

import math

import numpy as np

FILE_GAP = 0.75  # metres a follower adds to the group's reach: one walks behind another
FILE_MAX = 6.0  # at most this much stretch, however large the group
ROBOT_AT_GOAL = 1.5  # metres: the robot is at its goal
ARRIVE_WITH = 20.0  # seconds after the robot a group arriving "with it" may be there
THERE_MARGIN = 1.5  # metres beyond its reach a member counts as at the robot's goal


def follow_distance(base: float, n: int) -> float:
    """The distance the nearest of `n` followers may keep behind the robot."""
    return round(base + min(FILE_GAP * max(n - 1, 0), FILE_MAX), 2)


class ArrivalWith:
    """When the robot first got to its goal, having driven there, and when each member first got within
    `reach` + THERE_MARGIN of that goal."""

    def __init__(self, goal: tuple[float, float] | None, start: tuple[float, float] | None, members: int,
                 reach: float) -> None:
        # a robot that waits or follows (goal = start) arrives nowhere: no arrival is judged
        self.goal = goal if goal is not None and start is not None and math.dist(goal, start) > 2 * ROBOT_AT_GOAL \
            else None
        self.reach = reach + THERE_MARGIN
        self.robot_at = math.inf
        self.member_at = np.full(members, np.inf)
        self.last_t = 0.0

    def add(self, t: np.ndarray, robot: np.ndarray, pos: np.ndarray) -> None:
        """t (F,), robot (F, >=2), pos (F, M, 2) of the members (NaN when absent)."""
        if self.goal is None or not t.size:
            return
        self.last_t = max(self.last_t, float(t[-1]))
        at = np.hypot(robot[:, 0] - self.goal[0], robot[:, 1] - self.goal[1]) <= ROBOT_AT_GOAL
        if math.isinf(self.robot_at) and at.any():
            self.robot_at = float(t[np.argmax(at)])
        d = np.hypot(pos[..., 0] - self.goal[0], pos[..., 1] - self.goal[1])
        there = np.isfinite(d) & (d <= self.reach)
        for j in np.flatnonzero(np.isinf(self.member_at) & there.any(axis=0)):
            self.member_at[j] = float(t[np.argmax(there[:, j])])

    def judged(self, need: int) -> tuple[bool | None, str]:
        """(True: `need` members got there within ARRIVE_WITH s of the robot; False: they did not; None: not
        judged, the robot has no goal or had not got there, or the run ended too soon), and the figure."""
        if self.goal is None:
            return None, ""
        if math.isinf(self.robot_at):
            return None, "the robot had not got to its goal when the run ended"
        late = np.sort(self.member_at - self.robot_at)
        if late.size < need or need <= 0:
            return None, ""
        worst = float(late[need - 1])
        if worst <= ARRIVE_WITH:
            when = "with it" if worst <= 0 else f"{worst:.0f} s after it"
            return True, f"at its goal {when} (it got there at t = {self.robot_at:.1f} s)"
        if math.isinf(worst):
            if self.last_t < self.robot_at + ARRIVE_WITH:
                return None, f"the robot got to its goal at t = {self.robot_at:.1f} s and the run ended " \
                             f"{self.last_t - self.robot_at:.0f} s later: run it longer"
            return False, f"not at its goal {self.last_t - self.robot_at:.0f} s after it got there"
        return False, f"at its goal {worst:.0f} s after it (more than {ARRIVE_WITH:g} s)"
