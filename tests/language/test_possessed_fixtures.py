"""A fixture said as a room's own ("the second platform's bench", "the ticket hall's machines", "the
fourth gate's seats") is that room's fixture, decided by the room said, its rank read as a rank; a room
with several things alike of those words is the room (language/room_fixtures.py)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

OWNED = [
    ("station", "Two commuters perch on the second platform's bench.", "platform_2_bench"),
    ("station", "Three commuters wait at the ticket hall's machines.", "ticket_machines"),
    ("airport", "Two pilots sit on the fourth gate's seats.", "gate_b2_seats"),
    ("airport", "Four travellers doze on gate B2's seats.", "gate_b2_seats"),
    ("mall", "A guard stands by the bookshop's till.", "book_till"),
    ("eval/understanding/worlds/stadium.yaml", "Two fans wait by the south concourse's bar.", "concourse_bar"),
]


@pytest.mark.parametrize("world, sentence, place", OWNED)
def test_a_rooms_own_fixture_is_that_fixture(world, sentence, place):
    reading = read_prompt(sentence, load_world(world))
    assert not reading.unknown_places
    assert reading.groups[0].location == place


def test_a_room_with_several_things_alike_is_the_room():
    reading = read_prompt("Two teens queue at the food court's counter.", load_world("mall"))
    assert reading.groups[0].location == "food_court"
