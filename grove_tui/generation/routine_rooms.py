"""The robot's route past people who react to it around a routine: "six patients queue at the pharmacy and
look at the robot", "visitors wander in the gift shop and keep away from the robot".

People whose whole activity is reacting to the robot start beside its route (planning.place_robot_reactors),
and a route fixed elsewhere is run through the rooms the sentence puts them in. People with a routine of their
own (reaction_routine.py) do it where the sentence says, which the robot's route need not pass: they would
never see the robot, and their reaction would go "not checked" or ✗ for want of it. So a robot that crosses
or patrols passes through the zone of each such routine too, as it does for plain reacting groups; for people
who walk somewhere and react on the way ("a teacher glances at the robot while she walks to the staff room"),
the zone they walk to, where they are once there.
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.generation.block_at_place import posts_on_the_route
from grove_tui.generation.reaction_routine import routine_of
from grove_tui.language.reading import PromptReading
from grove_tui.world.model import World

Point = tuple[float, float]
_STAYING = frozenset({"queue", "wait", "converse", "wander"})


def routine_zone(world: World, group_index: int, reading: PromptReading | None) -> str | None:
    """The zone a group that reacts to the robot around a routine stays in (or walks to), or None."""
    if reading is None or not 0 <= group_index < len(reading.groups):
        return None
    g = reading.groups[group_index]
    if not g.robot_interaction or g.robot_interaction == "follow" or g.intent not in ("robot", *_STAYING, "walk"):
        return None
    if g.intent == "robot" and routine_of(g) is None and not g.destination:
        return None  # their whole activity is the reaction: placed beside the route (planning.place_robot_reactors)
    for place in (g.location, g.destination, g.start):
        zone = world.zone_of_place(place or "")
        if zone:
            return zone
    return None


def rooms_of_routines(world: World, reading: PromptReading | None, route: Sequence[Point] | None) -> list[str]:
    """The zones where people react to the robot around a routine that the robot's route does not pass."""
    if reading is None:
        return []
    rooms: list[str] = []
    for i in range(len(reading.groups)):
        zone = routine_zone(world, i, reading)
        if zone and zone not in rooms and posts_on_the_route(world, zone, route, 1) is None:
            rooms.append(zone)
    return rooms
