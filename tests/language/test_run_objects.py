""""Run" with a thing as its object (issue 29): "two volunteers run a quiz in the lounge" is doing
something there, not running; a fronted "While ..." clause before a robot's keeps that place. Real spaCy,
real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, place", [
    ("residential", "While two volunteers run a quiz in the lounge, the robot carries a parcel to the kitchen.",
     "living_room"),
    ("hospital", "While two nurses run a handover in the cafeteria, the robot takes the linen from the main "
     "entrance to the pharmacy.", "cafeteria"),
    ("residential", "Two volunteers run a quiz in the lounge.", "living_room"),
])
def test_running_a_thing_somewhere_keeps_them_there(read, world, prompt, place):
    group = read(world, prompt).groups[0]
    assert group.intent != "walk"
    assert group.location == place


def test_running_laps_is_still_moving(read):
    group = read("residential", "Two kids run laps of the hall.").groups[0]
    assert group.intent == "wander"


def test_running_somewhere_is_still_a_walk(read):
    group = read("hospital", "Two nurses run to the pharmacy.").groups[0]
    assert (group.intent, group.destination) == ("walk", "pharmacy")
