"""Leaving said by "out by" a door (round 50): "get out by the side door", "nip out by the fire exit".
The door is where they leave the scene, as for "leave by" and "out through"; "in by" a door is still
where they come in from, and "out by" something that is no door is left to the other passes."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,destination", [
    ("mall", "Shoppers get out by the west doors.", "west_entrance"),
    ("mall", "Two lads slip out by the fire exit.", "north_exit"),
    ("station", "A couple of commuters nip out by the side doors to the taxi rank.", "south_entrance"),
])
def test_out_by_a_door_is_where_they_leave(read, world, prompt, destination):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.start, g.destination) == ("walk", None, destination)


def test_out_by_a_door_keeps_where_they_were(read):
    (g,) = read("mall", "Shoppers in the food court go out by the west doors.").groups
    assert (g.start, g.destination) == ("food_court", "west_entrance")


def test_in_by_a_door_is_still_where_they_come_from(read):
    (g,) = read("hospital", "Two nurses come in by the garden door.").groups
    assert g.start == "cafeteria_terrace_door"
