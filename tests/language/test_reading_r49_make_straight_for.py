"""Round 49: "make straight for X", "make directly for X", "make a beeline for X" are going to X, as "head
straight for X" is; the adverb the parser takes for an adjective of "make" does not hide the going."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,destination", [
    ("hospital", "An orderly makes straight for the pharmacy.", "pharmacy"),
    ("hospital", "Three visitors make a beeline for the cafeteria, not the shop.", "cafeteria"),
    ("mall", "A couple of teenagers made directly for the food court.", "food_court"),
])
def test_making_straight_for_a_place_is_walking_there(read, world, prompt, destination):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.destination) == ("walk", destination)
