"""Breaking off from a group to do something at a place (issue 29): they walk there, not wait where the
group is. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, goal", [
    ("hospital", "Of the six nurses at the nurses station, two peel away to fetch linen from the store room.",
     "supply_room"),
    ("mall", "Three shoppers split off to grab popcorn at the cinema.", "cinema_lobby"),
    ("food_bank", "Of the eleven volunteers on the packing line, two break off to restock from the warehouse "
     "shelving.", "warehouse_shelving"),
])
def test_breaking_off_to_do_something_at_a_place_is_going_there(read, world, prompt, goal):
    group = read(world, prompt).groups[-1]
    assert group.intent == "walk"
    assert group.destination == goal
