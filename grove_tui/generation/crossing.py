"""Where a robot asked to cross a room with nowhere named to go ends up: out of the room by the door
across its widest stretch, so that, setting off from the far side (planning's start picker), it drives
across the room and out ("the robot crosses the main waiting room": from one wall to the door opposite,
not from the middle to the nearest door)."""

from __future__ import annotations

from typing import Protocol

import numpy as np

from grove_tui.world import World
from grove_tui.world.model import Door

Point = tuple[float, float]
BEYOND = 2.0  # metres past the door, in the next room


class _Picker(Protocol):
    def pick(self, place: str, towards: Point | None, away_from: Point | None = None) -> Point: ...


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
