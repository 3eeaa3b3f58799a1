"""A wandering verb with "from X to Y" is a walk to Y (issue 29), also after a fronted participle
("Carrying a picnic basket, two grandparents stroll from X to Y"). Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, goal", [
    ("town_square", "Carrying a picnic basket, two grandparents stroll from the fountain to the market stalls.",
     "fountain", "market_stalls"),
    ("zoo", "Holding hands, a young couple mosey from the gift shop to the penguin pool.",
     "gift_shop", "penguin_pool_rail"),
])
def test_wandering_from_somewhere_to_somewhere_is_a_walk(read, world, prompt, start, goal):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.start, group.destination) == ("walk", start, goal)


def test_wandering_from_shop_to_shop_stays_a_wander(read):
    assert read("zoo", "Three teenagers wander from shop to shop.").groups[0].intent == "wander"
