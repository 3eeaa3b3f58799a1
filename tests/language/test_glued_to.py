"""Someone kept at a place by their attention (language/glued_to.py): "glued to the whiteboard", "rooted to
the printer" is being there, no walk; "glued to her phone" and "glued to the robot" are left as they were."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,location", [
    ("office", "A manager is glued to the whiteboard while two interns chat in the kitchen.", "whiteboard"),
    ("office", "Two developers sit rooted to the printer.", "printer"),
    ("station", "A commuter stays riveted to the departure board on platform 1.", "departure_board"),
])
def test_glued_to_a_place_is_staying_there(read, world, prompt, location):
    group = read(world, prompt).groups[0]
    assert group.intent == "wait" and group.location == location and group.destination is None


def test_glued_to_a_phone_is_no_place(read):
    reading = read("office", "An intern is glued to her phone in the kitchen.")
    assert reading.groups[0].location == "kitchen" and reading.unknown_places == ()


def test_glued_to_the_robot_is_following_it(read):
    group = read("office", "A cleaner is glued to the robot.").groups[0]
    assert group.robot_interaction == "follow"
