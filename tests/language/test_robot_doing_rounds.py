"""The robot's patrol said in chat as rounds or laps it is doing ("robot doing rounds", "bot on rounds",
"the robot is doing laps of the yard"): a patrol (language/robot_on_patrol.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "5 ppl in the lobby, bot on rounds"),
    ("museum", "school trip: 20 kids in the cafe, robot doing rounds"),
    ("station", "2 guards at the ticket office, robot doing laps"),
    ("recycling_centre", "busy sat morning, the robot is doing laps of the site road"),
])
def test_rounds_the_robot_is_doing_are_a_patrol(read, world, prompt):
    reading = read(world, prompt)
    assert reading.robot is not None and reading.robot.task == "patrol"
