"""Round 44: wandering from one shop (or a shop's department) to another with no errand is browsing one's
way round: the people wander, from the first to the second. With somewhere else to go, or an errand,
a verb of wandering is a walk there."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("mall", "Two teenagers wander from the electronics store over to the toy shop.", "electronics_store", "toy_store"),
    ("mall", "A pair of grannies meander from the clothes shop to the bookshop.", "clothing_store", "bookshop"),
    ("diy_store", "Two lads in paint-spattered overalls drift from the paint aisle over to lighting.",
     "paint_department", "lighting_department"),
])
def test_wandering_between_shops_is_browsing(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.start, g.destination) == ("wander", start, destination)


@pytest.mark.parametrize("world,prompt,destination", [
    ("mall", "A security guard strolls from the toy store over to the cinema lobby.", "cinema_lobby"),
    ("mall", "Two teenagers wander from the electronics store to the toy shop to buy a present.", "toy_store"),
    ("airport", "Four couples stroll from the duty free to the café.", "cafe"),
])
def test_wandering_somewhere_else_or_on_an_errand_is_walking(read, world, prompt, destination):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.destination) == ("walk", destination)
