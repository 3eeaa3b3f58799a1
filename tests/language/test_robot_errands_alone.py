"""Round 54 (r54a): the robot carrying a thing from one place to another, with nobody named, is a robot
task alone: no group of people is made up (language/robot_alone_errands.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("hotel", "The robot carries a crate of towels from the laundry to reception."),
    ("hospital", "The robot takes a box of gloves up to the ward."),
    ("nightclub", "The robot fetches a tray of glasses from the upstairs bar down to the cellar."),
])
def test_a_robot_errand_with_a_thing_makes_up_nobody(read, world, prompt):
    reading = read(world, prompt)
    assert reading.groups == () and reading.robot is not None and reading.robot.task == "cross"


@pytest.mark.parametrize("world,prompt", [
    ("hotel", "The robot carries a tray through the busy lobby."),
    ("hospital", "The robot takes a group of visitors to the ward."),
])
def test_people_said_or_a_crowd_keep_a_group(read, world, prompt):
    assert len(read(world, prompt).groups) == 1
