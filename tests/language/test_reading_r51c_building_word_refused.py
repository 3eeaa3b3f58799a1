"""A place the world lacks, said with a word for the building before it ("the hospital canteen"), is
refused, after "bound for" as after "to": the building word says which building, not what kind of place,
so it brings no place of the world nearer by meaning. A place the world has under another word is still
read by meaning. Real spaCy, understanding worlds, no model."""

from __future__ import annotations

from functools import cache

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world.loader import load_world
from grove_tui.world.model import World


@cache
def _world(name: str) -> World:
    return load_world(f"eval/understanding/worlds/{name}.yaml")


REFUSED = [
    ("hospice", "A nurse leaves reception, bound for the hospital canteen.", "canteen"),
    ("hospice", "Two volunteers walk from the chapel to the hospital canteen.", "canteen"),
    ("dialysis_unit", "Both trainee nurses slip out of the clean utility, bound for the hospital canteen.",
     "canteen"),
]


@pytest.mark.parametrize(("world", "sentence", "head"), REFUSED)
def test_absent_place_with_a_building_word_is_refused(world: str, sentence: str, head: str) -> None:
    reading = read_prompt(sentence, _world(world))
    assert any(head in u for u in reading.unknown_places), reading.unknown_places
    assert all(g.destination is None for g in reading.groups)


def test_a_place_the_world_has_is_still_read() -> None:
    reading = read_prompt("A nurse leaves reception, bound for the canteen.", _world("care_home"))
    assert reading.groups[0].destination == "dining_room"
