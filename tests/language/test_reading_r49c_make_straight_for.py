""""Make straight for" (or "directly", "right") is going, like "make for": the adverb between "make" and
"for" keeps the verb of going and its destination. Real spaCy, understanding worlds, no model."""

from __future__ import annotations

from functools import cache

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world.loader import load_world
from grove_tui.world.model import World


@cache
def _world(name: str) -> World:
    return load_world(name)


CASES = [
    ("eval/understanding/worlds/hotel.yaml", "Three guests make directly for the restaurant.", "restaurant"),
    ("eval/understanding/worlds/library.yaml", "A student makes straight for the reading room.", "reading_room"),
]


@pytest.mark.parametrize(("world", "sentence", "destination"), CASES)
def test_make_straight_for(world: str, sentence: str, destination: str) -> None:
    reading = read_prompt(sentence, _world(world))
    assert len(reading.groups) == 1, reading.groups
    group = reading.groups[0]
    assert (group.intent, group.destination) == ("walk", destination)
