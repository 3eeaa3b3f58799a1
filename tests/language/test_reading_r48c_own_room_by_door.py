"""A person's own room said by its door ("locks his office door") where the words "office door" or
"bedroom door" name the door of another room of that kind: the owner says which room it is, so they
start in their own room, not at the other room's door. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, destination", [
    ("primary_school", "The headmistress locks her office door and goes to the staff room.", "head_office", "staff_room"),
    ("town_hall", "The mayor locks his office door and walks to the council chamber.", "mayors_parlour", "council_chamber"),
    ("residential", "The children bang their bedroom door and hurry to the living room.", "child_bedroom", "living_room"),
])
def test_the_owners_room_not_the_other_rooms_door(read, world, prompt, start, destination):
    group = read(world, prompt).groups[0]
    assert (group.start, group.destination) == (start, destination)
