"""Round 46 (r46a): a place named by a word and its number after "for" ("leaves the ticket hall for
platform 2", "quits the lounge for gate B2") is where they go, not a purpose (numbered_names.py); and what a
purpose is done with stays in it ("to help with the deliveries", purpose_with.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("station", "A guard leaves the ticket hall for platform 2 to meet the train.", "ticket_hall", "platform_2"),
    ("airport", "A pilot quits the lounge for gate B2 to check the rota.", "airline_lounge", "gate_b2"),
])
def test_a_numbered_place_after_for_is_the_destination(read, world, prompt, start, destination):
    (group,) = read(world, prompt).groups
    assert (group.start, group.destination) == (start, destination)
    assert group.purpose is not None and group.purpose.startswith("to ")


@pytest.mark.parametrize("world,prompt,purpose", [
    ("hospital", "A porter goes to the pharmacy to help with the deliveries.", "to help with the deliveries"),
    ("airport", "A cleaner walks over to gate B2 to deal with a spill.", "to deal with a spill"),
])
def test_what_a_purpose_is_done_with_stays_in_it(read, world, prompt, purpose):
    (group,) = read(world, prompt).groups
    assert group.purpose == purpose


def test_a_person_a_purpose_is_done_with_is_left_out(read):
    (group,) = read("airport", "A pilot heads to gate B1 to chat with the captain.").groups
    assert group.purpose == "to chat"
