"""A robot that passes people goes on past them: its way does not end (or start) beside them.

"Fourteen patients queue at the pharmacy and look at the robot as it passes" (hospital, no place for the
robot): the start/goal pair chosen across the scene (planning._chosen_pair) was the one whose way came
nearest the people who react, and with a long queue that was a pair whose goal lay beside the queue: the
robot parked there, "as it passes" lasted 80 s and the look read ✗ at 12/14. Unless the sentence sends it
there, a robot passes people and goes on: pairs whose ends are PASS_BY or more from every one of them come
first (`ends_off`), the others only when none of those passes them; and a way that still ends beside
them goes on from there to the nearest place PASS_BY or more from all of them, farther on (`goes_on`).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import TypeVar

import numpy as np

from grove_tui.scenario.reach import PASS_BY
from grove_tui.errors import PlanningError

Point = tuple[float, float]
Pair = TypeVar("Pair", bound=tuple[float, Point, Point])


def ends_off(pairs: Sequence[Pair], staying: Sequence[Point]) -> list[tuple[list[Pair], bool]]:
    """The tries over `pairs` (score, start, goal): those with both ends PASS_BY or more from every staying
    point, taken only if one passes them (False: no settling for the nearest miss); then all of them, as
    before (True)."""
    if not staying:
        return [(list(pairs), True)]

    def clear(p: Point) -> bool:
        return all(math.dist(p, q) >= PASS_BY for q in staying)

    return [([pair for pair in pairs if clear(pair[1]) and clear(pair[2])], False), (list(pairs), True)]


def goes_on(start: Point, goal: Point, path: np.ndarray, staying: Sequence[Point], candidates: Sequence[Point],
            plan_path: Callable[[Point, Point, bool], np.ndarray], may_cross: bool) -> tuple[Point, Point, np.ndarray]:
    """(start, goal, path), the goal moved on past them when it lies within PASS_BY of one of them: to the
    nearest candidate PASS_BY or more from all of them and farther from the start than they are, the way
    on from the old goal added to the path."""
    if not staying or all(math.dist(goal, q) >= PASS_BY for q in staying):
        return start, goal, path
    beyond = max(math.dist(start, q) for q in staying)
    onward = sorted((c for c in candidates if all(math.dist(c, q) >= PASS_BY for q in staying)
                     and math.dist(start, c) > beyond), key=lambda c: (math.dist(goal, c), c))
    for c in onward[:10]:
        try:
            leg = plan_path(goal, c, may_cross)
        except PlanningError:
            continue
        return start, c, np.concatenate([np.asarray(path, dtype=float).reshape(-1, 2),
                                         np.asarray(leg, dtype=float).reshape(-1, 2)[1:]])
    return start, goal, path
