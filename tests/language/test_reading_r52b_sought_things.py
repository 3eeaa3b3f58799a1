"""What a purpose seeks ("to look for X", "to hunt for X", "to shop for X"): the thing is the purpose's,
no place and no stay. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, thing, destination", [
    ("mall", "A couple walk from the food court to the cinema to hunt for a charger.", "charger", "cinema_lobby"),
    ("mall", "Three teenagers wander over to the toy shop to shop for birthday presents.", "presents", "toy_store"),
    ("garden_centre", "An old man strolls to the houseplants to search for a cactus.", "cactus", None),
])
def test_the_thing_sought_is_the_purpose(read, world, prompt, thing, destination):
    reading = read(world, prompt)
    assert reading.unknown_places == ()
    group = reading.groups[0]
    assert thing in (group.purpose or "")
    if destination is not None:
        assert group.destination == destination


def test_looking_for_a_while_is_no_thing(read):
    reading = read("mall", "Two friends walk to the toy shop to look for a while.")
    assert "while" not in (reading.groups[0].purpose or "") or reading.groups[0].destination == "toy_store"
