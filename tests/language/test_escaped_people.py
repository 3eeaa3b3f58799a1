"""Getting away from a person is no evacuation (language/escaped_people.py): "escapes from his mum and runs off
into X" goes to X; escaping or fleeing a place or a danger still evacuates."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

AWAY_FROM_SOMEONE = [
    ("mall", "A little girl escapes from her dad and dashes into the toy store.", "toy_store"),
    ("hospital", "A confused patient flees from the nurses and runs off to the cafeteria.", "cafeteria"),
    ("station", "A boy escapes from his nan and darts onto the concourse.", "concourse"),
]


@pytest.mark.parametrize("world, sentence, destination", AWAY_FROM_SOMEONE)
def test_escaping_from_a_person_is_going_off(world, sentence, destination):
    group = read_prompt(sentence, load_world(world)).groups[0]
    assert (group.intent, group.destination) == ("walk", destination)


def test_fleeing_a_place_is_still_an_evacuation():
    group = read_prompt("Shoppers flee the food court when the fire alarm goes off.", load_world("mall")).groups[0]
    assert (group.intent, group.start) == ("evacuate", "food_court")
