"""Where a robot asked to cross a room with nowhere named to go ends up: out of the room by the door
across its widest stretch, so that, setting off from the far side (planning's start picker), it drives
across the room and out ("the robot crosses the main waiting room": from one wall to the door opposite,
not from the middle to the nearest door); and where it sets off to cross a room: by the wall across from
where it goes."""

from __future__ import annotations

from typing import Protocol

import numpy as np
import shapely

from grove_tui.world import World
from grove_tui.world.model import Door

Point = tuple[float, float]
BEYOND = 2.0  # metres past the door, in the next room


class _Picker(Protocol):
    def pick(self, place: str, towards: Point | None, away_from: Point | None = None) -> Point: ...


class _Cells(Protocol):
    def cells(self, zone: str) -> np.ndarray: ...


class StartPicking(Protocol):
    @property
    def space(self) -> _Cells: ...

    def acceptable(self, p: Point) -> bool: ...


def crossing_goal(world: World, picker: _Picker, zone: str, cells: np.ndarray) -> Point | None:
    """A point just past the door of `zone` farthest from the zone's far wall, in the room it leads to;
    None when the zone has no door to another room (or no free floor)."""
    doors = [d for d in world.doors_of(zone) if not d.exit] or world.doors_of(zone)
    doors = [d for d in doors if _other_side(d, zone) is not None]
    if not doors or not len(cells):
        return None

    def reach(door: Door) -> float:
        return float(np.max(np.hypot(cells[:, 0] - door.position[0], cells[:, 1] - door.position[1])))

    door = max(doors, key=lambda d: (reach(d), d.name))
    other = _other_side(door, zone)
    assert other is not None
    beyond = door.outward_point(BEYOND) if door.zone == zone else door.inward_point(BEYOND)
    return picker.pick(other, towards=(float(beyond[0]), float(beyond[1])))


def _other_side(door: Door, zone: str) -> str | None:
    other = door.leads_to if door.zone == zone else door.zone
    return None if door.exit or other in ("", "outside", zone) else other


def crossing_start(world: World, picker: StartPicking, zone: str, goal: Point) -> Point | None:
    """A free point by the wall of `zone` across from `goal` (not wedged in a corner: of the points by the
    wall within a quarter of the zone's width of the farthest, the one nearest the zone's anchor); None
    when the zone has no such point. The start picker's far side (80 % as far as the farthest point) is,
    for a goal far off, most of the room: the robot set off from its middle, half a crossing."""
    polygon = world.zone(zone).polygon
    cells = picker.space.cells(zone)
    if not len(cells):
        return None
    width = _width(polygon)
    edge = 0.6 * max(1.5, 0.25 * width)  # well inside what the report counts as the zone's edge
    to_wall = shapely.distance(polygon.boundary, shapely.points(cells))
    ok = np.array([to_wall[k] <= edge and picker.acceptable((float(x), float(y)))
                   for k, (x, y) in enumerate(cells)], dtype=bool)
    if not ok.any():
        return None
    pts = cells[ok]
    d = np.hypot(pts[:, 0] - goal[0], pts[:, 1] - goal[1])
    far = np.flatnonzero(d >= d.max() - 0.25 * width)
    anchor = world.zone(zone).anchor
    k = int(far[np.argmin(np.hypot(pts[far, 0] - anchor[0], pts[far, 1] - anchor[1]))])
    return (round(float(pts[k, 0]), 3), round(float(pts[k, 1]), 3))


def _width(polygon: shapely.Polygon) -> float:
    xs, ys = polygon.minimum_rotated_rectangle.exterior.coords.xy
    sides = [float(np.hypot(xs[i + 1] - xs[i], ys[i + 1] - ys[i])) for i in range(2)]
    return min(sides) if min(sides) > 0 else max(sides)
