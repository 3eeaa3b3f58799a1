"""Round 50 (r50c): "stroll off towards X" is a walk to X, in any world ("off" is no place and no going
away from the scene)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,destination", [
    ("hospital", "Two nurses stroll off towards the pharmacy.", "pharmacy"),
    ("mall", "A couple strolls off towards the food court.", "food_court"),
    ("station", "Two commuters wander off towards platform 1.", "platform_1"),
])
def test_strolling_off_towards_a_place_is_a_walk_there(read, world, prompt, destination):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.destination) == ("walk", destination)
