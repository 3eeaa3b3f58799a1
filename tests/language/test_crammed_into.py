"""Round 54 (r54a): people who "are crammed/packed/squeezed into X" are in X, not going there; a subset
said after them goes on from there (language/crammed_into.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,place", [
    ("hotel", "Forty fans are packed into the bar.", "bar"),
    ("hotel", "Twelve guests are squeezed into the lift; two of them walk to the bar.", "lift_lobby"),
    ("office", "A dozen interns were all wedged into meeting room 1, and three of them drift to the kitchen.",
     "meeting_room_1"),
])
def test_crammed_into_a_place_is_being_there(read, world, prompt, place):
    groups = read(world, prompt).groups
    assert groups[0].location == place and groups[0].destination is None
    for subset in groups[1:]:
        assert subset.relation == "subset_of:0" and subset.destination is not None


def test_cramming_in_is_still_going_in(read):
    (group,) = read("hotel", "Twelve guests squeeze into the lift.").groups
    assert group.destination == "lift_lobby"
