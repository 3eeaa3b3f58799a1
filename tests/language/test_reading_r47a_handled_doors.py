"""A person's own room said by its door as what they shut or lock before setting off ("The manager locks
his office door and walks to the kitchen"): the door is a thing of that room, so the room is where they
start, not the door. Going out by the door still goes through the door. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, destination", [
    ("office", "The manager locks his office door and walks to the kitchen.", "manager_office", "kitchen"),
    ("residential", "Mum closes her bedroom door and goes down to the kitchen.", "master_bedroom", "kitchen"),
])
def test_a_handled_door_of_ones_own_room_starts_in_the_room(read, world, prompt, start, destination):
    group = read(world, prompt).groups[0]
    assert (group.start, group.destination) == (start, destination)


def test_leaving_by_ones_office_door_is_still_the_door(read):
    group = read("office", "The manager leaves by his office door.").groups[0]
    assert group.start != "manager_office"
