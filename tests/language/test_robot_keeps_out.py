"""The robot kept out of a place ("drives to the pharmacy, avoiding the cafeteria", "without going through
the main waiting room", "keeps out of", "steers clear of", "never enters", fronted or after): the place is
its `avoid`, never its start, destination, location or via (language/kept_away.py, robot_avoided.py)."""

from __future__ import annotations

import pytest

from grove_tui.language.model import RobotReading

CASES = [
    # (world, prompt, avoid, start, destination)
    ("hospital", "A robot crosses from reception to the pharmacy without going through the main waiting room.",
     ("main_waiting_room",), "reception_desk", "pharmacy"),
    ("hospital", "The robot drives to the pharmacy but keeps out of the cafeteria.", ("cafeteria",), None, "pharmacy"),
    ("hospital", "The robot delivers medicines from the pharmacy to ward B, avoiding the cafeteria.",
     ("cafeteria",), "pharmacy", "ward_b"),
    ("hospital", "Avoiding the cafeteria, the robot drives to the pharmacy.", ("cafeteria",), None, "pharmacy"),
    ("hospital", "The robot drives to the pharmacy and never enters the cafeteria.", ("cafeteria",), None, "pharmacy"),
    ("hospital", "The robot must avoid the cafeteria on its way to the pharmacy.", ("cafeteria",), None, "pharmacy"),
    ("hospital", "The robot drives from radiology to the pharmacy, not via the main waiting room.",
     ("main_waiting_room",), "radiology", "pharmacy"),
    ("station", "The robot crosses from the ticket hall to platform 1 without going through the concourse.",
     ("concourse",), "ticket_hall", "platform_1"),
    ("station", "The robot goes to platform 2, steering clear of the ticket hall.", ("ticket_hall",), None,
     "platform_2"),
    ("mall", "The robot rolls to the bookshop but keeps out of the food court.", ("food_court",), None, "bookshop"),
    ("mall", "Staying out of the food court, the robot heads to the bookshop.", ("food_court",), None, "bookshop"),
    ("airport", "The robot drives to gate A1 and never goes through security.", ("security_checkpoint",), None,
     "gate_a1"),
    ("hospital", "The robot drives to the pharmacy and stays away from the cafeteria.", ("cafeteria",), None,
     "pharmacy"),
    ("hospital", "The robot drives to the pharmacy and doesn't go through the cafeteria.", ("cafeteria",), None,
     "pharmacy"),
    ("office", "The robot goes to the boardroom without entering the kitchen.", ("kitchen",), None, "boardroom"),
]


@pytest.mark.parametrize("world,prompt,avoid,start,destination", CASES)
def test_the_place_kept_out_of_is_the_robots_avoid_and_none_of_its_places(read, world, prompt, avoid, start,
                                                                          destination):
    robot = read(world, prompt).robot
    assert robot is not None and robot.task == "cross"
    assert robot.avoid == avoid
    assert (robot.start, robot.destination) == (start, destination)
    used = {robot.start, robot.destination, robot.location, *robot.via}
    assert not used & set(avoid)


@pytest.mark.parametrize("prompt,location,via", [
    ("The robot waits outside the cafeteria.", "main_corridor", ()),
    ("The robot crosses the cafeteria.", None, ("cafeteria",)),
    ("The robot drives through the cafeteria to the pharmacy.", None, ("cafeteria",)),
])
def test_being_by_or_going_through_a_place_is_no_avoid(read, prompt, location, via):
    robot = read("hospital", prompt).robot
    assert robot is not None and robot.avoid == ()
    assert robot.location == location and robot.via == via


def test_a_group_still_reads_its_own_avoid_and_the_robot_none(read):
    reading = read("hospital", "Three porters walk from radiology to the cafeteria but keep out of the main waiting "
                               "room while the robot drives to the pharmacy.")
    (porters,) = reading.groups
    assert porters.avoid == ("main_waiting_room",) and porters.destination == "cafeteria"
    assert reading.robot is not None and reading.robot.avoid == () and reading.robot.destination == "pharmacy"


def test_the_avoid_round_trips_and_an_old_reading_without_it_loads():
    robot = RobotReading("cross", destination="pharmacy", avoid=("cafeteria",))
    assert RobotReading.from_dict(robot.to_dict()) == robot
    old = robot.to_dict()
    del old["avoid"]
    assert RobotReading.from_dict(old).avoid == ()
