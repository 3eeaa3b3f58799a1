"""What carries the load people push ("pushes the bags on a cart", "wheels the compost on a trolley")
is how the load goes, no place: never the world's trolley bay or luggage trolleys as the start; the
"from" phrase is. "the trolleys" with "the" stays to the reader. Real spaCy, understanding worlds,
no model."""

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
    ("diy_store", "Two staff push sheets of plywood on a trolley from the timber department to the tills.",
     "timber_department", "tills"),
    ("garden_centre", "A worker wheels sacks of compost on a trolley from the entrance to the tills.",
     "entrance_lobby", "tills"),
    ("supermarket", "A worker wheels sacks of compost on a trolley from the entrance to the tills.",
     "entrance_lobby", "checkouts"),
]


@pytest.mark.parametrize(("world", "sentence", "start", "destination"), CASES)
def test_the_carrier_of_the_load_is_no_place(world: str, sentence: str, start: str, destination: str) -> None:
    reading = read_prompt(sentence, _world(world))
    assert (reading.groups[0].start, reading.groups[0].destination) == (start, destination)
    assert reading.unknown_places == ()
