"""People taken along or sent named with a possessive and a count (round 71): "leads her twelve pupils",
"wheels his two grandchildren": a group of that many, not lost."""

from __future__ import annotations

import pytest

CASES = [
    ("library", "A teacher walks her thirty pupils to the reading room.", 30, "follow"),
    ("airport", "A dad wheels his two toddlers to gate B1.", 2, "follow"),
    ("hospital", "The charge nurse sends her four students to the cafe.", 4, "walk"),
]


@pytest.mark.parametrize(("world", "prompt", "count", "intent"), CASES)
def test_the_counted_object_is_a_group(read, world, prompt, count, intent):
    groups = read(world, prompt).groups
    assert len(groups) == 2
    taken = next(g for g in groups if g.count.value == count)
    assert taken.intent == intent


def test_the_robot_takes_them_along(read):
    reading = read("museum", "The robot guides his three nieces to the cafe.")
    assert [g.count.value for g in reading.groups] == [3]
    assert reading.robot is not None and reading.robot.task == "cross"


@pytest.mark.parametrize(("world", "prompt"), [
    ("library", "The teacher brings her class to the seminar room."),
    ("airport", "A tour rep leads his group to gate A2."),
])
def test_a_possessed_collective_follows(read, world, prompt):
    groups = read(world, prompt).groups
    assert len(groups) == 2
    leader, led = groups
    assert leader.intent == "walk" and led.intent == "follow" and led.follows == leader.who
