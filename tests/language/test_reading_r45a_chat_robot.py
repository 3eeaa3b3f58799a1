"""Round 45: a chat list that ends with the robot's task keeps it. The robot before a route drawn with an
arrow ("bot ward b -> ICU") crosses it, and the robot before a bare "-ing" verb ("robot making its rounds")
is doing it; the people listed before keep their places."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, destination", [
    ("hospital", "3 nurses at the pharmacy, bot ward b -> ICU", "ward_b", "intensive_care"),
    ("office", "2 devs in the kitchen. robot: reception → kitchen", "reception", "kitchen"),
])
def test_the_robot_before_an_arrow_crosses(read, world, prompt, start, destination):
    reading = read(world, prompt)
    assert (reading.robot.task, reading.robot.start, reading.robot.destination) == ("cross", start, destination)
    assert len(reading.groups) == 1 and reading.groups[0].intent == "wait"


@pytest.mark.parametrize("world, prompt, task", [
    ("station", "3 guards at the gateline, robot making its rounds", "patrol"),
    ("research_lab_building", "2 postdocs in the tc lab, robot patrolling", "patrol"),
])
def test_the_robot_before_a_bare_ing_verb_does_it(read, world, prompt, task):
    reading = read(world, prompt)
    assert reading.robot.task == task and reading.groups[0].count.value in (2, 3)
