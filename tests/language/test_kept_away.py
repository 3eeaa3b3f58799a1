"""Probe round r64c: "keeping away from the X" / "staying well clear of the X" after a mover's clause
is a place not to use, never the mover's start (language/kept_away.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,destination", [
    ("hospital", "The robot drives to radiology, staying well clear of the cafeteria.", "radiology"),
    ("station", "The robot crosses to platform 1 staying away from the ticket hall.", "platform_1"),
    ("mall", "The robot rolls to the bookshop, keeping away from the food court.", "bookshop"),
])
def test_a_place_kept_away_from_is_no_start_of_the_robot(read, world, prompt, destination):
    robot = read(world, prompt).robot
    assert robot is not None and robot.destination == destination
    assert robot.start is None


def test_keeping_away_from_the_robot_is_still_a_reaction(read):
    (group,) = read("airport", "Two passengers walk to gate A1, keeping away from the robot.").groups
    assert group.robot_interaction == "avoid" and group.destination == "gate_a1"
