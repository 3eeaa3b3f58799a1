"""A bare "-side" word ("rinkside", "trackside", "ringside") right after the people of a chat list's item
with no verb is where they are; one the world has no alias for names the zone of the thing before "side"
("trackside" where the world has a track), with a verb, after "at", or bare. Real spaCy, understanding
worlds, no model."""

from __future__ import annotations

from functools import cache

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world.loader import load_world
from grove_tui.world.model import World


@cache
def _world(name: str) -> World:
    return load_world(f"eval/understanding/worlds/{name}.yaml")


CASES = [
    ("karting_centre", "12 drivers on the track, 2 marshals trackside", "marshal", "track"),
    ("karting_centre", "Two marshals stand trackside.", "marshal", "track"),
    ("county_show", "about 30 spectators in the grandstand, 4 stewards ringside", "steward", "ring_fence"),
    ("ice_rink", "approx 40 skaters on ice, 3 marshals rinkside", "marshal", "rinkside"),
]


@pytest.mark.parametrize(("world", "sentence", "label", "location"), CASES)
def test_bare_side_word(world: str, sentence: str, label: str, location: str) -> None:
    reading = read_prompt(sentence, _world(world))
    group = next(g for g in reading.groups if g.label == label)
    assert group.location == location
