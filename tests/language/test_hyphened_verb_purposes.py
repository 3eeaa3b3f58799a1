"""A verb written with a hyphen after "to" ("keen to test-drive the estate car", "to spot-check the tills")
is a purpose, not a way to a place (language/hyphened_verbs.py)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

SHOWROOM = "eval/understanding/worlds/car_showroom.yaml"
PURPOSES = [
    (SHOWROOM, "A couple stroll into the showroom, keen to test-drive the estate car.", "showroom", "estate car"),
    (SHOWROOM, "A lad heads to the showroom to test-drive the SUV.", "showroom", "SUV"),
    ("mall", "A manager walks to the food court to spot-check the tills.", "food_court", "tills"),
]


@pytest.mark.parametrize("world, sentence, destination, thing", PURPOSES)
def test_a_hyphened_verb_after_to_is_a_purpose(world, sentence, destination, thing):
    reading = read_prompt(sentence, load_world(world))
    assert not reading.unknown_places
    group = reading.groups[0]
    assert group.destination == destination
    assert group.purpose is not None and thing in group.purpose
