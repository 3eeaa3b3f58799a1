"""Places a group must keep out of ("avoiding the lifts", "but not through the lobby"): their shapes,
and a planner on the grid with them blocked, so the waypoints of that group go round them.

An exit the sentence rules out is not here: evacuees take the nearest other exit (postprocess's exit
choice); this is for the places on the way."""

from __future__ import annotations

from collections.abc import Sequence

import shapely

from grove_tui.errors import WorldError
from grove_tui.navigation.grid import OccupancyGrid, with_blocked
from grove_tui.navigation.theta_star import ThetaStarPlanner
from grove_tui.world.model import Entity, World, Zone

# Metres kept between the group's paths and what it avoids: a walker's body (0.25 m) and the social
# force's push leave a path that grazes a blocked cell inside it.
ZONE_MARGIN = 0.3
# A thing or a door is a point to the sentence ("avoiding the fountain"): this far round it.
POINT_RADIUS = 1.5


def keep_out_shape(world: World, name: str) -> shapely.Geometry | None:
    """The ground a group keeps out of for a place the sentence rules out (None for an unknown name)."""
    try:
        place = world.find(name)
    except WorldError:
        return None
    if isinstance(place, Zone):
        return place.polygon.buffer(ZONE_MARGIN)
    if isinstance(place, Entity):
        return place.polygon.buffer(POINT_RADIUS)
    return shapely.Point(place.position).buffer(POINT_RADIUS)  # a door


def keep_out_planner(world: World, grid: OccupancyGrid, names: Sequence[str]) -> ThetaStarPlanner | None:
    """A planner that never crosses the places `names` (None when none of them has a shape)."""
    shapes = [s for s in (keep_out_shape(world, n) for n in names) if s is not None]
    if not shapes:
        return None
    return ThetaStarPlanner(with_blocked(grid, shapes), landmarks=0)
