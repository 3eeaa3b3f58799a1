"""Where a robot asked to pass a desk, a door or a thing sets off and ends: away from it, on either side,
so that it comes to it and leaves it ("a librarian looks up as the robot passes the desk").

The start picker put such a robot at the place itself (the free point nearest the desk, 1 m from it), and
the report's "robot via issue_desk" was ✓ at t = 0.1 s without the robot ever coming to the desk. Now it
sets off AWAY metres or more from it (in the desk's room when there is floor enough, else in the next room),
and a goal nobody named is on the desk's far side from its start, AWAY metres or more from it too; the path
is then made to pass by the desk's point (planning's via spots). The report counts the pass only once the
robot came to the desk from elsewhere (outcomes._RobotPlaceProbe).
"""

from __future__ import annotations

import math

import numpy as np

from grove_tui.generation.crossing import StartPicking
from grove_tui.world import World

Point = tuple[float, float]
AWAY = 5.0  # metres from the place passed the robot starts and ends
AIM = 8.0  # metres: of the points far enough, the one nearest this far (not the far end of the building)
ACROSS = 110.0  # degrees: the goal is on the far side (the angle start-spot-goal at least this)


def _candidates(world: World, picker: StartPicking, spot: Point) -> list[np.ndarray]:
    """Free floor the robot may start on, AWAY or more from `spot`: its own zone's first, then its
    neighbours' (through a door)."""
    own = world.zone_at(spot[0], spot[1])
    names = [own.name] if own is not None else []
    if own is not None:
        names += sorted({d.leads_to if d.zone == own.name else d.zone for d in world.doors_of(own.name)}
                        - {own.name, "", "outside"})
    known = {z.name for z in world.zones}
    out = []
    for name in (n for n in names if n in known):
        pts = picker.space.cells(name)
        if not len(pts):
            continue
        d = np.hypot(pts[:, 0] - spot[0], pts[:, 1] - spot[1])
        out.append(pts[d >= AWAY])
    return out


def _best(pts: np.ndarray, spot: Point, picker: StartPicking, keep: np.ndarray | None = None) -> Point | None:
    if not len(pts):
        return None
    d = np.hypot(pts[:, 0] - spot[0], pts[:, 1] - spot[1])
    order = np.argsort(np.abs(d - AIM), kind="stable")
    for k in order:
        if keep is not None and not keep[k]:
            continue
        p = (round(float(pts[k, 0]), 3), round(float(pts[k, 1]), 3))
        if picker.acceptable(p):
            return p
    return None


def _angle(a: np.ndarray, spot: Point, b: Point) -> np.ndarray:
    """Degrees at `spot` between each point of `a` and `b`."""
    u = a - np.asarray(spot)
    v = np.asarray(b) - np.asarray(spot)
    cos = (u @ v) / np.maximum(np.hypot(u[:, 0], u[:, 1]) * math.hypot(*v), 1e-9)
    return np.asarray(np.degrees(np.arccos(np.clip(cos, -1.0, 1.0))))


def ends_off_the_spot(world: World, picker: StartPicking, spot: Point | None, start: Point | None,
                      goal: Point | None) -> tuple[Point | None, Point | None]:
    """(start, goal) for a robot that passes `spot`: a start within AWAY of it moved off it (to the side away
    from the goal when there is one), and a missing goal put on its far side; either left as it is when no
    floor fits."""
    if spot is None:
        return start, goal
    groups = _candidates(world, picker, spot)
    if start is None or math.dist(start, spot) < AWAY:
        moved = None
        for pts in groups:
            keep = None if goal is None else _angle(pts, spot, goal) >= ACROSS
            moved = _best(pts, spot, picker, keep)
            if moved is not None:
                break
        start = moved or start
    if goal is None and start is not None:
        for pts in groups:
            goal = _best(pts, spot, picker, _angle(pts, spot, start) >= ACROSS)
            if goal is not None:
                break
    return start, goal
