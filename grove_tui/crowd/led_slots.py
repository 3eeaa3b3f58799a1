"""Where people the robot leads walk: their place behind it, not the robot itself.

"The robot leads thirty patients to the exit": ApproachRobot sent every follower to a point a metre
short of the robot on the line from them. Thirty people converging on one point pressed round it,
some stepped in front of it, and the robot's collision monitor held it at its creep speed: the run took
twice as long as planned. A follower of a leading robot (ApproachRobot with `behind` > 0) instead
walks to a spot `behind` metres behind the robot along its heading, in rows of up to MAX_COLUMNS people
abreast, spread by its place among the robot's followers (the order they first asked for a spot). The
robot keeps its pace; the followers keep up and arrive with it. A place on the far side of a wall
(nearest free floor to a point beside a robot driving along it) is never used: it led people along
the wrong side of the wall, away from the robot.
"""

from __future__ import annotations

import math

from grove_tui.crowd.context import Point, SimContext

MAX_COLUMNS = 5  # followers abreast behind the robot at most (a compact block: about as wide as deep)
SLOT_SIDE = 0.7  # metres between followers side by side
SLOT_ROW = 0.8  # metres between rows of followers
SLOT_EASE = 1.0  # metres: slows as d / (d + SLOT_EASE) near its place, stops short of a robot that stops
CATCH_UP = 3.0  # metres beyond its place within which a follower takes it (further off it walks at the robot)


def slot_of(sim: SimContext, row: int) -> int:
    """The row's place among the robot's followers, given once (first come, first placed)."""
    slots = sim.led_slots
    if row not in slots:
        slots[row] = len(slots)
    return slots[row]


def slot_offset(slot: int, behind: float, followers: int = 1) -> tuple[float, float]:
    """(metres back along the robot's heading, metres to its left) of a follower's place among `followers`."""
    columns = max(2, min(MAX_COLUMNS, math.ceil(math.sqrt(max(followers, 1)))))
    rank, column = divmod(slot, columns)
    return behind + rank * SLOT_ROW, (column - (columns - 1) / 2.0) * SLOT_SIDE


def slot_behind(sim: SimContext, row: int, robot: tuple[float, float, float], behind: float) -> Point | None:
    """The free point a follower of the robot walks to: its place behind the robot (module doc), in the
    robot's sight; narrower (straight behind it) where a wall cuts the place off. None while the follower
    is far from the robot or out of its sight (it catches up walking at the robot, round corners and
    through doors as before), or when even the narrow place is out of the robot's sight."""
    here = sim.pos[row]
    back, left = slot_offset(slot_of(sim, row), behind, len(sim.led_slots))
    if math.dist(here, robot[:2]) > back + CATCH_UP or not sim.sees(here, robot[:2]):
        return None
    room = _zone(sim, robot[0], robot[1])
    if room != _zone(sim, here[0], here[1]):
        return None  # in the next room (through a door, across a wall): to the robot first
    c, s = math.cos(robot[2]), math.sin(robot[2])
    for b, l in ((back, left), (back, 0.0), (behind, 0.0)):
        spot = sim.nearest_free(robot[0] - b * c - l * s, robot[1] - b * s + l * c)
        if _zone(sim, *spot) == room and sim.sees(robot[:2], spot) and sim.sees(here, spot):
            return spot
    return None


def _zone(sim: SimContext, x: float, y: float) -> str | None:
    world = sim.world
    zone = world.zone_at(x, y) if world is not None else None
    return zone.name if zone is not None else None
