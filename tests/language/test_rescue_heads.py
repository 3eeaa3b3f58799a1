"""A place the world lacks that shares only a modifier with one it has ("the tea tent" where there is
a "tea bar") is refused, not read by meaning as that place (rescue_heads)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


@pytest.mark.parametrize("world, sentence, refused, start", [
    (W + "stadium.yaml", "Three mates stroll out of the family zone towards the tea tent.", "tea tent", "family_zone"),
    (W + "cricket_ground.yaml", "A foursome of lads in county shirts stroll out of the tea room towards the beer tent.",
     "beer tent", "tea_room"),
])
def test_a_shared_modifier_rescues_no_place(world, sentence, refused, start):
    reading = read_prompt(sentence, load_world(world))
    assert reading.unknown_places == (refused,)
    assert (reading.groups[0].start, reading.groups[0].destination) == (start, None)
