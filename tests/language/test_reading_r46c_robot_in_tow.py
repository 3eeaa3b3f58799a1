"""Round 46: a person the robot has in tow ("With X in tow, the robot ...", "the robot ... with X in tow",
"the robot, towing X, ...") follows the robot while the robot does its own task; a thing in tow is no one."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, destination, people", [
    ("hospital", "The robot heads to the pharmacy with two porters in tow.", None, "pharmacy", 2),
    ("office", "The robot, with a lost visitor in tow, drives from reception to the kitchen.", "reception", "kitchen", 1),
    ("supermarket", "Towing a small boy, the robot rolls to the checkout.", None, "checkouts", 1),
    ("hotel", "With a tired, elderly guest in tow, the robot crosses the lobby to the lifts.", None, None, 1),
])
def test_a_person_in_tow_follows_the_robot(read, world, prompt, start, destination, people):
    reading = read(world, prompt)
    assert reading.robot is not None and reading.robot.task == "cross"
    if start is not None:
        assert reading.robot.start == start
    if destination is not None:
        assert reading.robot.destination == destination
    assert [(g.robot_interaction, g.count.value) for g in reading.groups] == [("follow", people)]


def test_a_thing_in_tow_is_nobody(read):
    reading = read("warehouse", "The robot crosses the floor with its cart in tow.")
    assert all(g.robot_interaction != "follow" for g in reading.groups)
