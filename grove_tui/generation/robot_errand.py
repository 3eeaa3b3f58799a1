"""The robot's errand as a plan: to the pick-up place first, a stop there, then to the drop-off.

"The robot carries books from the returns desk to the reading room" (language/robot_errands.py): the robot
sets off from a room next to the desk's (not the reading room), drives to the desk, stands there
PICKUP_SECONDS (RobotSpec.stops; simulation/robot.py holds it there), then drives to the reading room. A
fetch with nowhere to take the thing goes back where it set off; a delivery with no pick-up place sets
off away from the drop-off. The report claims both legs (reconcile._robot_row through `errand_claims`):
a stop at the pick-up place, and the drop-off reached after it (analysis/robot_errand.py checks them).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Protocol

import numpy as np

from grove_tui.errors import GenerationError
from grove_tui.language.robot_errands import RobotErrand
from grove_tui.scenario.model import RobotSpec
from grove_tui.scenario.report import Claim
from grove_tui.world.model import World

PICKUP_SECONDS = 5.0  # the stop at the pick-up place (seconds standing still)
STOP_SPEED = 0.05  # m/s: standing still, for the check
PLACE_RADIUS = 1.5  # metres around a thing's or door's point that count as there

Point = tuple[float, float]


class _Picker(Protocol):
    def pick(self, place: str, towards: Point | None, away_from: Point | None = None) -> Point: ...


def _neighbours(world: World, zone: str) -> list[str]:
    """The rooms a door of `zone` leads to (not outside)."""
    out: list[str] = []
    for door in world.doors_of(zone):
        for other in (door.zone, door.leads_to):
            if other and other != zone and other not in out and world.zone_of_place(other) == other:
                out.append(other)
    return out


def _start_beside(world: World, picker: _Picker, pickup: str, pickup_point: Point, avoid_zone: str | None) -> Point:
    """Where an errand sets off: in a room next to the pick-up place's (not the drop-off's), else in the
    pick-up room itself as far from the pick-up point as the picker allows."""
    zone = world.zone_of_place(pickup) or pickup
    for other in sorted(_neighbours(world, zone), key=lambda z: (z == avoid_zone, z)):
        if other == avoid_zone:
            continue
        try:
            return picker.pick(other, towards=None, away_from=pickup_point)
        except GenerationError:
            continue
    return picker.pick(zone, towards=None, away_from=pickup_point)


def errand_robot(world: World, picker: _Picker, place_point: Callable[[str], Point | None],
                 plan_path: Callable[[Point, Point, bool], np.ndarray], errand: RobotErrand,
                 notes: list[str], through: Callable[[np.ndarray, Point, Point], np.ndarray] | None = None,
                 ) -> RobotSpec | None:
    """The robot's start, path and stop for an errand; None when its places have no point (the caller
    plans the plain crossing). `through`: the leg with the thing made to pass the rooms of people who react
    to the robot (planning._through)."""
    drop_point = place_point(errand.dropoff) if errand.dropoff else None
    if errand.dropoff and drop_point is None:
        return None
    drop_zone = world.zone_of_place(errand.dropoff) if errand.dropoff else None
    if errand.pickup is None:
        assert drop_point is not None
        start = _start_beside(world, picker, errand.dropoff or "", drop_point, None)
        path = plan_path(start, drop_point, True)
        path = through(path, start, drop_point) if through is not None else path
        notes.append(f"the robot {errand.kind}s to {errand.dropoff}: it sets off from the next room")
        return RobotSpec(start=start, goal=drop_point, path=_rounded(path), task="cross")
    pick_point = place_point(errand.pickup)
    if pick_point is None:
        return None
    start = _start_beside(world, picker, errand.pickup, pick_point, drop_zone)
    goal = drop_point if drop_point is not None else start
    there = plan_path(start, pick_point, True)
    back = plan_path(pick_point, goal, True)
    back = through(back, pick_point, goal) if through is not None else back
    path = np.concatenate([there, back[1:]])
    where = errand.dropoff or "where it set off"
    notes.append(f"the robot's errand: from the next room to {errand.pickup}, a {PICKUP_SECONDS:g} s stop there "
                 f"to pick up, then to {where}")
    stop = (round(pick_point[0], 3), round(pick_point[1], 3), PICKUP_SECONDS)
    return RobotSpec(start=start, goal=goal, path=_rounded(path), task="cross", stops=(stop,))


def _rounded(path: np.ndarray) -> tuple[Point, ...]:
    return tuple((round(float(x), 3), round(float(y), 3)) for x, y in path)


def _place_claim_fields(world: World, place: str, point: Point | None) -> tuple[str | None, Point | None, float]:
    zone = world.zone_of_place(place)
    if zone == place:
        return zone, None, 0.0
    return None, point, PLACE_RADIUS


def errand_claims(errand: RobotErrand, robot: RobotSpec, world: World, seconds: float) -> tuple[Claim, ...]:
    """The two legs the report claims: a stop at the pick-up place, the drop-off reached after it."""
    claims: list[Claim] = []
    needs = round(seconds * 1.3 + 10.0 + PICKUP_SECONDS, 1)
    if errand.pickup is not None and robot.stops:
        x, y, hold = robot.stops[0]
        zone, point, radius = _place_claim_fields(world, errand.pickup, (x, y))
        claims.append(Claim("robot_pickup", f"pick up at {errand.pickup}",
                            f"drive to {errand.pickup} first and stop there {hold:g} s", zone=zone,
                            place=errand.pickup, point=point, radius=radius, seconds=hold, needs_seconds=needs))
    if errand.dropoff is not None:
        zone, point, radius = _place_claim_fields(world, errand.dropoff, robot.goal)
        plan = f"then drive to {errand.dropoff}" if claims else f"drive to {errand.dropoff} and stop there"
        claims.append(Claim("robot_dropoff", f"drop off at {errand.dropoff}", plan, zone=zone,
                            place=errand.dropoff, point=point, radius=radius, seconds=PICKUP_SECONDS,
                            needs_seconds=needs))
    else:
        claims.append(Claim("robot_dropoff", "bring it back where it set off", "then drive back to its start",
                            point=(round(robot.goal[0], 3), round(robot.goal[1], 3)), radius=PLACE_RADIUS,
                            seconds=PICKUP_SECONDS, needs_seconds=needs))
    return tuple(claims)


def errand_length(robot: RobotSpec) -> float:
    path: Sequence[Point] = robot.path or (robot.start, robot.goal)
    return sum(math.dist(a, b) for a, b in zip(path, path[1:]))
