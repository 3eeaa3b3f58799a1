"""Where a robot sent through people sets off: "the robot drives through the queue to the cafeteria",
"threads its way through the crowd of visitors in the waiting room to the lifts".

A robot sent through a zone starts at the zone's far side from its goal. When its clause goes through people
who stay in that zone (they queue, wait, talk or wander there: `RobotReading.passes`), starting inside it puts the robot among them before a queue has
formed and sends it away from them; it sets off from the next room instead, on the side away from its goal,
so its way runs through the zone while they are there (the report checks it came within reach of them,
`reconcile.PASSING_DISTANCE`).

Queues and conversation circles are obstacles the robot's planner keeps clear of (`formations.py`). The ones
those people form are not: the clause asks the robot through them, so its way passes by a gap in the line
(`through_formations`); it stops and creeps there as it does for anyone in its way (simulation/robot.py).
"""

from __future__ import annotations

import math

from grove_tui.generation.formations import Formation
from grove_tui.generation.reaction_routine import routine_of
from grove_tui.language.passing_manner import passes_through
from grove_tui.language.reading import PromptReading
from grove_tui.navigation.grid import OccupancyGrid
from grove_tui.world.model import World

_STAYING = frozenset({"queue", "wait", "converse", "wander"})

Point = tuple[float, float]


def passed_zones(reading: PromptReading | None, world: World) -> dict[int, str]:
    """Reading group index -> the zone it stays in, for the groups the robot's clause goes through
    (`RobotReading.passes`) that stay in one zone: the people it is asked to pass, and where."""
    if reading is None or reading.robot is None or not reading.robot.passes:
        return {}
    passes = set(reading.robot.passes)
    out: dict[int, str] = {}
    for i, g in enumerate(reading.groups):
        # people who only react to the robot stay where they are unless sent somewhere (reconcile's base intent)
        intent = g.intent if g.intent != "robot" else routine_of(g) or ("walk" if g.destination else "wait")
        place = g.location or (g.destination if intent in _STAYING else None)
        zone = world.zone_of_place(place or "")
        if g.who in passes and intent in _STAYING and zone is not None:
            out[i] = zone
    return out


def people_stay_in(reading: PromptReading | None, world: World, place: str) -> bool:
    """Whether a group the robot's clause goes through stays in the zone of `place`."""
    zone = world.zone_of_place(place)
    return zone is not None and zone in passed_zones(reading, world).values()


def zone_before(world: World, place: str, goal: Point | None) -> str | None:
    """The zone next to the zone of `place` (through a door) farthest from `goal`, the robot's goal:
    where it sets off to pass through; None when the zone has no inside neighbour."""
    zone = world.zone_of_place(place)
    if zone is None:
        return None
    goal_zone = _zone_name(world, *goal) if goal is not None else None
    names = {z.name for z in world.zones}
    neighbours = {d.leads_to if d.zone == zone else d.zone for d in world.doors_of(zone)}
    neighbours = {n for n in neighbours if n in names and n not in (zone, goal_zone)}
    if not neighbours:
        return None
    if goal is None:
        return sorted(neighbours)[0]
    return max(sorted(neighbours), key=lambda n: math.dist(world.zone(n).anchor, goal))


def through_formations(reading: PromptReading | None, world: World, grid: OccupancyGrid,
                       formations: list[Formation]) -> tuple[list[Formation], list[Point]]:
    """(the formations the robot still keeps clear of, the points its way must pass by): a queue or
    conversation in a zone where people the robot's clause goes through stay is no obstacle, and the robot
    passes by its gap (`gap_point`)."""
    zones = set(passed_zones(reading, world).values())
    if not zones or not passes_through(reading.robot if reading is not None else None):
        return formations, []  # "drives past them": the line stays an obstacle it passes beside (past_queue.py)
    kept: list[Formation] = []
    spots: list[Point] = []
    for formation in formations:
        if not any(_zone_name(world, x, y) in zones for x, y in formation.line):
            kept.append(formation)
            continue
        gap = gap_point(formation)
        free = grid.nearest_free(gap[0], gap[1], max_dist=1.0)
        if free is None:  # no floor in the gap: the line stays an obstacle
            kept.append(formation)
        else:
            spots.append((float(free[0]), float(free[1])))
    return kept, spots


def gap_point(formation: Formation) -> Point:
    """Where a robot goes through a formation: a queue between its second and third places (people join at
    the front first, and the one being served is not cut off), or between its first two places when it is
    shorter; a conversation through its centre."""
    slots = formation.line[1:] if formation.kind == "queue" else formation.line
    if len(slots) < 2:
        return slots[0] if slots else formation.line[0]
    a, b = (slots[1], slots[2]) if len(slots) >= 3 else (slots[0], slots[1])
    return ((a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0)


def _zone_name(world: World, x: float, y: float) -> str | None:
    zone = world.zone_at(x, y)
    return zone.name if zone is not None else None
