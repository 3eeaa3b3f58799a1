"""Floating, bobbing, paddling or wading along water is being in it, not a walk through it (lexicon's
wander verbs): "30ish bathers bob along the lazy river" are in the river."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,place", [
    ("water_park", "A dozen teenagers float down the lazy river on rubber rings.", "lazy_river"),
    ("water_park", "Two dads wade about in the toddlers' splash zone.", "splash_zone"),
    ("swimming_baths", "A few pensioners bob about in the shallow end.", None),
])
def test_floating_along_water_is_being_there(read, world, prompt, place):
    (group,) = read(world, prompt).groups
    assert group.intent == "wander" and group.destination is None
    if place is not None:
        assert group.location == place
