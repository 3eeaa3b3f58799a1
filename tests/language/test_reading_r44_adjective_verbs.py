"""Round 44: an adjective of a thing that is also a verb of a chore ("carries clean linen", "fetches a
clean gown") is no chore: the robot or the person carrying it goes from where it is fetched to where it is
taken (a "cross" for the robot), not about a room."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "The robot carries clean linen from the supply room to ward B while two nurses chat at the "
                 "nurses' station.", "supply_room", "ward_b"),
    ("hotel", "The robot carries clean sheets from the laundry to room 105.", "laundry", "room_105"),
])
def test_the_robot_carrying_clean_things_crosses(read, world, prompt, start, destination):
    robot = read(world, prompt).robot
    assert robot is not None
    assert (robot.task, robot.start, robot.destination) == ("cross", start, destination)


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "A porter carries clean linen from the supply room to ward B.", "supply_room", "ward_b"),
    ("hotel", "A chambermaid takes clean towels from the laundry up to room 105.", "laundry", "room_105"),
])
def test_a_person_carrying_clean_things_walks(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.start, g.destination) == ("walk", start, destination)


def test_a_chore_verb_is_still_a_chore(read):
    (g,) = read("hospital", "A cleaner cleans the main corridor.").groups
    assert (g.intent, g.location) == ("wander", "main_corridor")
