"""People whose reaction is tied to the robot passing a named place stand at that place.

"Visitors look up as the robot passes the ticket desk" (station, museum): the visitors only react, and the
sentence puts them nowhere, so planning stood them beside the robot's route a third of the way along it,
near its start; they looked at it long before it came by the desk, and the look read ✗ (checked only while
the robot passes the desk, generation/passing_look.py): a true figure of a wrong scenario. A group whose
reaction the sentence ties to the robot passing a place (language/passing_moment.py) is now placed beside
the robot's route where it passes that place (`passing_points`: the group's index to the place's point;
planning.place_robot_reactors anchors them at the route's samples nearest to it), and the robot's route goes
past the place (the place is its via).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Protocol

import numpy as np

from grove_tui.language.model import PromptReading

Point = tuple[float, float]


class _Group(Protocol):
    @property
    def index(self) -> int: ...
    @property
    def reading_index(self) -> int | None: ...
    @property
    def reacts_only(self) -> bool: ...


def passing_points(reading: PromptReading | None, groups: Sequence[_Group],
                   point_of: Callable[[str], Point | None]) -> dict[int, Point]:
    """For each group that only reacts and whose reaction is tied to the robot passing a named place: the
    group's index to that place's point."""
    out: dict[int, Point] = {}
    if reading is None:
        return out
    for g in groups:
        index = g.reading_index
        if not g.reacts_only or index is None or index >= len(reading.groups):
            continue
        passed = reading.groups[index].passed_place
        if not reading.groups[index].reacts_as_robot_passes or passed is None:
            continue
        point = point_of(passed)
        if point is not None:
            out[g.index] = (float(point[0]), float(point[1]))
    return out


def nearest_first(samples: np.ndarray, point: Point) -> np.ndarray:
    """The route's samples by their distance to `point`, nearest first (where the robot passes the place)."""
    return np.argsort(np.hypot(samples[:, 0] - point[0], samples[:, 1] - point[1]), kind="stable")


def off_the_route(pts: np.ndarray, route: np.ndarray, near: float) -> np.ndarray:
    """(N,) whether each of `pts` is at least `near` from every sample of the robot's `route`: a reactor's band
    was measured from one anchor on the route only, and where the route bends a guard was stood 0.2 m from a
    later leg of it (the robot came within 0.5 m of him as it passed the desk)."""
    if not len(route) or not len(pts):
        return np.ones(len(pts), dtype=bool)
    gap = np.full(len(pts), np.inf)
    for k in range(0, len(route), 256):
        part = route[k:k + 256]
        gap = np.minimum(gap, np.min(np.hypot(pts[:, None, 0] - part[None, :, 0], pts[:, None, 1] - part[None, :, 1]),
                                     axis=1))
    return gap >= near
