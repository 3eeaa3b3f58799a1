""""From where X is done" names the place where that is done, by its use, and ends at the "to" that names
the destination: "wheels a clothes rail from where the costumes get sewn to the stage" walks from the
wardrobe to the stage. A thing pushed along ("wheels a roll cage", "pushes a trolley") is what is moved,
not where the walk starts. Real spaCy, understanding worlds, no model."""

from __future__ import annotations

from functools import cache

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world.loader import load_world
from grove_tui.world.model import World

PLAYHOUSE = "eval/understanding/worlds/playhouse.yaml"
HOTEL = "eval/understanding/worlds/hotel.yaml"


@cache
def _world(name: str) -> World:
    return load_world(name)


CASES = [
    (PLAYHOUSE, "A dresser wheels a clothes rail from where the costumes get sewn to the stage.", "wardrobe", "stage"),
    (PLAYHOUSE, "Two stagehands walk from the room where the costumes are mended to the green room.", "wardrobe",
     "green_room"),
    (HOTEL, "A chef pushes a trolley from where the plates go out to the restaurant tables.", "kitchen",
     "restaurant_tables"),
]


@pytest.mark.parametrize(("world", "sentence", "start", "destination"), CASES)
def test_from_where_it_is_done(world: str, sentence: str, start: str, destination: str) -> None:
    reading = read_prompt(sentence, _world(world))
    assert len(reading.groups) == 1, reading.groups
    group = reading.groups[0]
    assert group.intent == "walk"
    assert (group.start, group.destination) == (start, destination)
