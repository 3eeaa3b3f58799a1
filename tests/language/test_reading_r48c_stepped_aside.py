"""A step back or aside from the robot goes nowhere: the place said with the person ("a student at the
issue desk steps back") is where they stay, their location, not a start. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, location", [
    ("library", "Startled, a student at the issue desk steps back as the robot rolls up.", "issue_desk"),
    ("hospital", "A porter by the lifts moves aside as the robot passes.", "elevator_hall"),
    ("office", "An intern at the printer steps aside to let the robot through.", "printer"),
])
def test_a_step_aside_stays_where_one_is(read, world, prompt, location):
    group = read(world, prompt).groups[0]
    assert (group.start, group.location, group.robot_interaction) == (None, location, "avoid")


def test_stepping_back_to_somewhere_still_goes_there(read):
    group = read("office", "An intern at the printer steps back to her desk as the robot passes.").groups[0]
    assert group.location is None
