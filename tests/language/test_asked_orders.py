"""An order said with "to" (round 71): "Tell ... to wait", "Get ... to walk", "I'd like ... to queue": the
person asked is a group doing the verb; the robot asked is left to the robot's reader."""

from __future__ import annotations

import pytest

CASES = [
    ("airport", "Ask four cleaners to wait by the check-in desks.", 4, "wait"),
    ("museum", "We'd like twelve pupils to queue at the cloakroom.", 12, "queue"),
    ("station", "Set the robot on platform 1, then tell two porters to walk to the ticket office.", 2, "walk"),
    ("library", "I need a student to wait at the issue desk.", 1, "wait"),
]


@pytest.mark.parametrize(("world", "prompt", "count", "intent"), CASES)
def test_the_person_asked_does_the_verb(read, world, prompt, count, intent):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    assert groups[0].count.value == count and groups[0].intent == intent


def test_the_robot_asked_is_no_group(read):
    reading = read("mall", "Get the robot to wait at the main entrance and tell three guards to stand by the fountain.")
    assert reading.robot is not None and reading.robot.task == "wait"
    assert [g.count.value for g in reading.groups] == [3]
