""""His office" said of the boss by an informal word for one ("the gaffer", "the guvnor") is the
manager's office, as it is for "the boss". Real spaCy, understanding worlds and the shipped office,
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
    ("high_street_bank", "two cashiers at the counter, the guvnor in his office", "guvnor", "manager_office"),
    ("parcel_depot", "A driver walks from the canteen to the inbound dock while the gaffer works in his office.",
     "gaffer", "depot_manager_office"),
]


@pytest.mark.parametrize(("world", "sentence", "label", "location"), CASES)
def test_the_informal_boss_has_the_managers_office(world: str, sentence: str, label: str, location: str) -> None:
    reading = read_prompt(sentence, _world(world))
    boss = next(g for g in reading.groups if g.label == label)
    assert boss.location == location
