"""A place headed by a word of the world's own name, with another noun before it ("the baby bank" in a
food bank, "the night club" at a tennis club), is another kind of that word, not the building: a world
without one refuses it. The building's own name, and a compound very near it in meaning, are still the
building. Real spaCy, understanding worlds, no model."""

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
    ("high_street_bank", "A clerk walks from the banking hall to the blood bank.", "blood bank", "banking_hall"),
    ("food_bank", "A mum and her son stroll from the porch over to the baby bank.", "baby bank", "porch"),
    ("tennis_club", "Three juniors run from the foyer to the night club.", "night club", "foyer"),
]


@pytest.mark.parametrize(("world", "sentence", "refused", "start"), REFUSED)
def test_another_kind_of_the_worlds_name_is_refused(world: str, sentence: str, refused: str, start: str) -> None:
    reading = read_prompt(sentence, _world(world))
    assert refused in reading.unknown_places, reading.unknown_places
    assert all(g.destination is None for g in reading.groups)
    assert reading.groups[0].start == start


def test_the_building_itself_is_not_refused() -> None:
    reading = read_prompt("Two volunteers leave the food bank by the front door.", _world("food_bank"))
    assert reading.unknown_places == ()
