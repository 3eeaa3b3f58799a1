"""A stay said before the people with a participle and the place it was spent at ("After ten minutes
hanging around the departure board, a commuter ..."): they start at that thing itself, not anywhere in
its room. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start", [
    ("station", "After ten minutes hanging around the departure board, a commuter heads down to platform 2.",
     "departure_board"),
    ("station", "After a quarter of an hour queuing by the ticket machines, two students walk over to the café.",
     "ticket_machines"),
    ("mall", "After twenty minutes sitting by the fountain, a shopper wanders to the food court.", "fountain"),
    ("hospital", "After half an hour loitering near the vending machine, a visitor walks to the pharmacy.",
     "vending_machine"),
])
def test_a_fronted_participle_stay_starts_at_its_thing(read, world, prompt, start):
    assert read(world, prompt).groups[0].start == start


def test_a_fronted_stay_without_a_place_keeps_the_start_unsaid(read):
    group = read("station", "After ten minutes reading, a commuter heads down to platform 2.").groups[0]
    assert group.start != "departure_board" and group.destination == "platform_2"
