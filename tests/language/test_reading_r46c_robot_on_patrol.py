"""Round 46: the robot's patrol said as a state ("bot on patrol along X", "the robot is out on patrol in X",
"robot on its rounds of X") is its patrol there; the people listed before keep their own places, and a
person "on patrol" is left to their own verb."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, location, people", [
    ("station", "3 guards at the gateline, robot on its rounds of the concourse", "concourse", 3),
    ("hospital", "Two nurses chat at the pharmacy while the robot is out on patrol in the main corridor.",
     "main_corridor", 2),
    ("library", "a few students reading in the quiet study area, robot on patrol", None, 3),
])
def test_the_robot_on_patrol_patrols(read, world, prompt, location, people):
    reading = read(world, prompt)
    assert reading.robot is not None and reading.robot.task == "patrol"
    assert reading.robot.location == location
    assert len(reading.groups) == 1 and reading.groups[0].count.value == people


def test_a_person_on_patrol_keeps_their_verb(read):
    reading = read("office", "The robot is on its usual rounds of the kitchen; a guard on patrol walks to reception.")
    assert reading.robot is not None and (reading.robot.task, reading.robot.location) == ("patrol", "kitchen")
    assert [(g.intent, g.destination) for g in reading.groups] == [("walk", "reception")]
