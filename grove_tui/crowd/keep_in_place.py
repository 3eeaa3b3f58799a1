"""Keeping away from the robot without leaving one's place (AvoidRobot in GROVE's crowd).

"Five visitors wander in the gift shop and keep away from the robot": HuNavSim's AvoidRobot runs straight
away from the robot to `safe_distance`, which out of a small shop is out of the shop (one visitor stayed
in the café for the rest of the run). A person keeping away gives way inside the zone they stood in when
the robot came (their place: the shop they wander, the hall they queue or talk in): to the free point of
that zone nearest to them that is `safe_distance` from the robot, else the one farthest from it; they
leave it only when the zone has no free floor at all.

A robot that has finished its drive and stands still is gone for this purpose: people keep a personal
distance (PARKED_DISTANCE) from it and otherwise go on with their routine (the reaction gives way to it),
rather than standing frozen at the edge of their room for the rest of the run.
"""

from __future__ import annotations

import math
import weakref

import numpy as np
import shapely

from grove_tui.crowd.context import Point, SimContext

SPOT_STEP = 0.5  # metres between the points of a zone a person may step to
WALL_MARGIN = 0.4  # metres the points keep inside the zone's outline
IN_ZONE_SLACK = 0.05  # metres past the outline still counted in the zone (rounding, not a doorway)
PARKED_DISTANCE = 3.0  # metres kept from a robot standing at the end of its drive
PARKED_SPEED = 0.05  # m/s: below this the robot stands

_spots: weakref.WeakKeyDictionary[SimContext, dict[str, np.ndarray]] = weakref.WeakKeyDictionary()
_driven: weakref.WeakSet[SimContext] = weakref.WeakSet()  # simulations whose robot was seen driving


def home_zone(sim: SimContext, point: Point) -> str | None:
    """The zone a person stands in (their place while they keep away), None without a world or outside."""
    if sim.world is None:
        return None
    zone = sim.world.zone_at(float(point[0]), float(point[1]))
    return zone.name if zone is not None else None


def in_zone(sim: SimContext, zone: str, point: Point) -> bool:
    """Whether a point is in `zone`, as the report's stay check judges it (its outline, a few centimetres
    for rounding): one who stepped half a metre past it into a doorway or the next room walks back in,
    where a slack of half a metre had left them standing there for good while the stay claim failed."""
    if sim.world is None:
        return True
    polygon = sim.world.zone(zone).polygon
    return bool(polygon.distance(shapely.Point(float(point[0]), float(point[1]))) <= IN_ZONE_SLACK)


def _zone_spots(sim: SimContext, zone: str) -> np.ndarray:
    cache = _spots.setdefault(sim, {})
    found = cache.get(zone)
    if found is not None:
        return found
    points = np.zeros((0, 2))
    if sim.world is not None:
        polygon = sim.world.zone(zone).polygon
        inner = polygon.buffer(-WALL_MARGIN)
        if inner.is_empty:
            inner = polygon
        x0, y0, x1, y1 = inner.bounds
        gx, gy = np.meshgrid(np.arange(x0, x1 + 1e-9, SPOT_STEP), np.arange(y0, y1 + 1e-9, SPOT_STEP))
        xs, ys = gx.ravel(), gy.ravel()
        inside = shapely.contains_xy(inner, xs, ys)
        xs, ys = xs[inside], ys[inside]
        free = np.array([sim.is_free(float(x), float(y)) for x, y in zip(xs, ys)], dtype=bool)
        points = np.column_stack([xs[free], ys[free]]) if free.any() else np.zeros((0, 2))
    cache[zone] = points
    return points


def target_in_place(sim: SimContext, zone: str | None, here: Point, robot: Point, safe_distance: float) -> Point | None:
    """Where in `zone` to step to keep away from the robot: the nearest point at `safe_distance` (and a
    little) from it, else the farthest from it (a little less for one far from here); None when the zone
    has no free point (the caller then runs straight away)."""
    if zone is None:
        return None
    spots = _zone_spots(sim, zone)
    if spots.shape[0] == 0:
        return None
    from_robot = np.hypot(spots[:, 0] - robot[0], spots[:, 1] - robot[1])
    from_here = np.hypot(spots[:, 0] - here[0], spots[:, 1] - here[1])
    far_enough = from_robot >= safe_distance + 0.3
    if far_enough.any():
        j = int(np.argmin(np.where(far_enough, from_here, np.inf)))
    else:
        j = int(np.argmax(from_robot - 0.3 * from_here))
    return (float(spots[j, 0]), float(spots[j, 1]))


def robot_parked(sim: SimContext) -> bool:
    """Whether the robot has finished its drive and stands still (a robot that waits where it is, never
    seen driving, has not gone anywhere: people keep their full distance from it)."""
    if sim.robot is None:
        return False
    if sim.robot_speed >= 0.2:
        _driven.add(sim)
    return sim in _driven and sim.robot_speed < PARKED_SPEED and bool(sim.crowd.robot_path_done)


def clear_of_parked_robot(sim: SimContext, here: Point, safe_distance: float) -> bool:
    """Whether a person keeping away may go on with their routine: the robot stands at the end of its
    drive and they are a personal distance from it."""
    robot = sim.robot
    if robot is None or not robot_parked(sim):
        return False
    return math.hypot(here[0] - robot[0], here[1] - robot[1]) >= min(safe_distance, PARKED_DISTANCE)
