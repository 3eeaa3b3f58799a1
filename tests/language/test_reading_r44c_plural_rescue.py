"""A place phrase about to be refused is read by meaning less strictly, and, when it is a plural, in the
singular too: "the stores" comes nearer "drugstore" by its letters than the hospital's "store room", but
"store" is clearly the store room. A world with no store of any kind still refuses it. Real spaCy, real
worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, role, place", [
    ("hospital", "A porter pops down to the stores to fetch clean linen for ward B.", "destination", "supply_room"),
    ("hospital", "A healthcare assistant wheels linen out of the stores up to ward 3.", "start", "supply_room"),
    ("hospital", "An orderly heads to the stores.", "destination", "supply_room"),
])
def test_the_stores_are_the_store_room(read, world, prompt, role, place):
    reading = read(world, prompt)
    assert reading.unknown_places == ()
    assert getattr(reading.groups[0], role) == place


@pytest.mark.parametrize("world, prompt", [
    ("office", "An intern walks to the stores for printer paper."),
    ("library", "A librarian walks to the stores."),
])
def test_a_world_without_a_store_still_refuses_them(read, world, prompt):
    assert "stores" in read(world, prompt).unknown_places
