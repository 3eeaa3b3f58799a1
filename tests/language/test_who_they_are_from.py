"""Round 54: "<people> from <a place the world lacks> <verb>" says who they are, nothing to refuse, and a
misspelt or noun-tagged verb of walking ("trapse", "traipse", "mooch") is the clause's verb, not the last
word of a place."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,destination", [
    ("zoo", "Twelve children from the primary school trapse over to the penguin pool.", "penguin_pool_rail"),
    ("zoo", "Twelve children from the primary school traipse over to the penguin pool.", "penguin_pool_rail"),
    ("hospital", "Two porters from the day ward hurry to the cafeteria.", "cafeteria"),
    ("museum", "A gang of teenagers from the youth club mooch over to the café.", "cafe"),
])
def test_people_from_a_place_the_world_lacks_are_not_refused(read, world, prompt, destination):
    r = read(world, prompt)
    assert not r.unknown_places
    (g,) = r.groups
    assert (g.intent, g.destination) == ("walk", destination)


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "Two porters from the cafeteria walk to ward B.", "cafeteria", "ward_b"),
    ("mall", "Two teens walk from the food court to the cinema.", "food_court", "cinema_lobby"),
])
def test_a_place_the_world_has_after_from_stays_the_start(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.start, g.destination) == (start, destination)
