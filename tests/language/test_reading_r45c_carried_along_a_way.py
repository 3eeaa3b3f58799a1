"""A thing carried from a start along a way to a destination ("takes the trolley from the kitchen along the
corridor to bedroom 3"): the way said between the two is a via, not part of the start's name. Real spaCy,
real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, via, destination", [
    ("hospital", "A porter wheels the linen cart from the supply room along the ward corridor to ward B.",
     "supply_room", "ward_corridor", "ward_b"),
    ("office", "The office junior takes the post from reception along the main corridor to the boardroom.",
     "reception", "main_corridor", "boardroom"),
    ("station", "A cleaner brings the mop bucket from the staff office across the concourse to the toilets.",
     "staff_office", "concourse", "toilets"),
    ("hospice", "An HCA takes the drinks trolley from the kitchen along the corridor to bedroom 3.",
     "kitchen", "ward_corridor", "bedroom_3"),
])
def test_a_way_between_start_and_destination_is_a_via(read, world, prompt, start, via, destination):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.start, group.destination) == ("walk", start, destination)
    assert via in group.via
