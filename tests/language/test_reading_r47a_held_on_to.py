"""Holding on to a place ("An unsteady patient clings to the reception desk", "Two toddlers hang on to
the fountain"): "to" after a verb of holding on is where they stay, not where they go. Real spaCy, real
worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, location", [
    ("hospital", "An unsteady patient clings to the reception desk while two porters walk to the pharmacy.",
     "reception_desk"),
    ("mall", "Two toddlers hang on to the fountain.", "fountain"),
    ("station", "A child holds on tight to the ticket machines.", "ticket_machines"),
])
def test_holding_on_to_a_place_is_staying_there(read, world, prompt, location):
    group = read(world, prompt).groups[0]
    assert (group.location, group.destination) == (location, None)


def test_walking_to_a_place_still_goes_there(read):
    group = read("mall", "Two toddlers run to the fountain.").groups[0]
    assert group.destination == "fountain"
