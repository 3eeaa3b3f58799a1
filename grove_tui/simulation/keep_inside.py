"""Nobody leaves the building unless their task is to leave it.

The crowd can push someone out through an exit's opening: a guard standing at the main entrance, a
guest stepping out of the robot's way by the lobby door. Removing them (as evacuees are removed once
out) made them vanish from the run, and every claim about them could no longer be told. Only people
whose tree walks them out (FollowVelocityField: evacuating, walking out through an exit) may leave;
anyone else the crowd pushes over the door line is held back in, as the door's jambs and a person's
own will would: put back at the nearest point of the building a body's width inside its outline,
standing, with a `kept_in` event saying where. Walking to an exit door is leaving too ("a family walks
out by the exit": GoTo the door), and so is following the robot (led out by it).
"""

from __future__ import annotations

from collections.abc import Collection, Sequence

import numpy as np
import shapely
import shapely.ops
from shapely.geometry.base import BaseGeometry

from grove_tui.bt.format.document import TreeDocument

LEAVING_NODES = frozenset({"FollowVelocityField"})  # the trees that walk a person out of the building
FOLLOWING_ROBOT_NODES = frozenset({"ApproachRobot"})  # led by the robot: out of the door when it goes out
KEEP_IN_MARGIN = 0.1  # metres beyond the person's radius they are put back inside the outline


def may_leave(documents: Sequence[TreeDocument | None], exit_names: Collection[str] = ()) -> np.ndarray:
    """Per row, whether the person's task is to leave the building: their tree walks them out by the
    field, goes to one of the exit doors `exit_names`, or follows the robot."""
    exits = frozenset(exit_names)

    def leaves(document: TreeDocument | None) -> bool:
        return document is not None and any(
            e.id in LEAVING_NODES or e.id in FOLLOWING_ROBOT_NODES or (e.id == "GoTo" and e.get("target") in exits)
            for e in document.nodes())

    return np.array([leaves(document) for document in documents], dtype=bool)


def back_inside(building: BaseGeometry, point: tuple[float, float], radius: float) -> tuple[float, float]:
    """The point of the building nearest to `point` that a body of `radius` stands in, clear of its outline."""
    inner = building.buffer(-(radius + KEEP_IN_MARGIN))
    if inner.is_empty:
        inner = building
    here = shapely.Point(point)
    if inner.contains(here):
        return point
    near = shapely.ops.nearest_points(inner, here)[0]
    return float(near.x), float(near.y)
