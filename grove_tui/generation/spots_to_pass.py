"""The robot comes by the door or thing where people wait to react to it.

"A porter stands at the hotel entrance and greets the robot": the porter approaches the robot at the
entrance, gated on the robot coming near (approach_at_place.py, block_at_place.py). Planning had the
robot's route pass through the *zones* of such places it missed; a door or a thing in a zone the route
already crosses was never passed by: the robot crossed the lobby 8 m from the entrance, the porter's
post stayed at the door, and the approach was a true ✗. For a place that is a door or a thing, the
route passes by the place's own point (a little inside a door), as a via point the sentence named would.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol

from grove_tui.generation.approach_at_place import approached_place
from grove_tui.generation.block_at_place import blocked_place, posts_on_the_route
from grove_tui.generation.draft import DraftNode
from grove_tui.navigation.grid import OccupancyGrid
from grove_tui.errors import WorldError
from grove_tui.world.model import Door, Entity, World

Point = tuple[float, float]
DOOR_INSIDE = 2.0  # metres inside a door the robot passes by (not through it: an exit leads out)


class _Grouped(Protocol):
    @property
    def tree(self) -> DraftNode: ...


def reacting_place(tree: DraftNode) -> str | None:
    """The place a group's tree waits at to react to the robot (approach or block at a place), or None."""
    return approached_place(tree) or blocked_place(tree)


def spots_to_pass(world: World, grid: OccupancyGrid, groups: Sequence[_Grouped],
                  route: Sequence[Point] | None) -> list[Point]:
    """Free points by the doors and things people react to the robot at that `route` does not pass."""
    out: list[Point] = []
    for g in groups:
        place = reacting_place(g.tree)
        if place is None or posts_on_the_route(world, place, route, 1) is not None:
            continue
        try:
            found = world.find(place)
        except WorldError:
            continue
        if isinstance(found, Door):
            point = found.inward_point(DOOR_INSIDE)
        elif isinstance(found, Entity):
            point = found.interaction_point
        else:
            continue  # a zone: its room is passed through (approach_at_place.rooms_to_pass)
        free = grid.nearest_free(float(point[0]), float(point[1]), max_dist=2.0)
        if free is not None and (spot := (round(float(free[0]), 3), round(float(free[1]), 3))) not in out:
            out.append(spot)
    return out
