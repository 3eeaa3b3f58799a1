"""Why a reaction to the robot could not fire: the robot never came near the people asked to react.

"... the receptionist looks up as the robot passes" while the robot follows a visitor, waits at the lifts or
drives a route elsewhere: the reaction claim read "✗ the robot never came within 10 m of them" (or ✗ "0/2
came within 2.5 m"), which says nothing a researcher can act on. Every reaction claim that does not hold
and whose people the robot never came within the reaction's reach of now says so, with what kept the robot
away (its task from the robot's row: the person it follows, the place it waits at, its route, or, where the
sentence gives it no task, the route planning chose) and how near it came, measured on the run.
"""

from __future__ import annotations

import numpy as np

from grove_tui.scenario.report import Claim, RobotGrounding

# the reach each reaction needs the robot within (generation/reconcile.REACTION_DISTANCE; a look: LOOK_RANGE)
REACH = {"robot_follow": 3.0, "robot_approach": 2.5, "robot_block": 2.5, "robot_avoid": 6.0, "robot_look": 10.0}


class Nearness:
    """The closest the robot came to each member of each group over the run (frames in time order)."""

    def __init__(self, cols: dict[int, np.ndarray]) -> None:
        self.cols = cols
        self.closest = {g: np.full(c.size, np.inf) for g, c in cols.items()}

    def add(self, pos: np.ndarray, robot: np.ndarray | None) -> None:
        if robot is None:
            return
        for g, cols in self.cols.items():
            if not cols.size:
                continue
            p = pos[:, cols]
            d = np.hypot(p[..., 0] - robot[:, 0:1], p[..., 1] - robot[:, 1:2])
            self.closest[g] = np.fmin(self.closest[g], np.nanmin(np.where(np.isfinite(d), d, np.inf), axis=0))


def kept_away(claim: Claim, closest: np.ndarray, robot: RobotGrounding | None) -> str:
    """The reason a reaction claim that did not hold could not fire for the members the robot never came
    within reach of, or "" when it came within reach of all (who then did not react, which the claim's own
    evidence says)."""
    reach = claim.distance or REACH.get(claim.kind)
    closest = np.asarray(closest, dtype=float).reshape(-1)
    far = closest[np.isfinite(closest)]
    if robot is None or reach is None or claim.kind not in REACH or not far.size:
        return ""
    far = far[far > reach]
    if not far.size:
        return ""
    what = f"'{robot.text}'" if robot.text else ""
    if robot.task == "follow":
        cause = f"the robot's task ({what or 'following someone'}) kept it away from"
    elif robot.task == "wait":
        cause = f"the robot's task ({what or 'waiting'}) kept it where it waits, away from"
    elif robot.task == "pass" or not robot.text:
        cause = "the robot's route (the sentence gives it no task; planning chose it) did not pass"
    else:
        cause = f"the robot's task ({what}: {robot.plan or robot.task}) kept its route away from"
    who = "them" if far.size == closest.size else f"{far.size} of them"
    return f"{cause} {who}: it came within {float(far.min()):.1f} m of {who}, a reaction needs {reach:g} m"
