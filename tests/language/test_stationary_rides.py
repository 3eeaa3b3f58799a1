"""A thing people ride that stays put ("pts on exercise bikes", "on static bikes") is the world's fixture
where it has one, no way of going (language/ridden_things.py); a wheelchair people sit in describes them,
and where they line up is the place (language/walking_aids.py)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

PHYSIO = "eval/understanding/worlds/physio_clinic.yaml"
REHAB = "eval/understanding/worlds/rehab_centre.yaml"
ON_FIXTURES = [
    (PHYSIO, "3 pts on exercise bikes, 1 physio @ the parallel bars", "exercise_bikes"),
    (REHAB, "two patients on static bikes in the gym", "exercise_bikes"),
    (REHAB, "2 pts on exercise bikes, bot on patrol", "exercise_bikes"),
]


@pytest.mark.parametrize("world, sentence, place", ON_FIXTURES)
def test_a_ride_that_stays_put_is_the_fixture(world, sentence, place):
    reading = read_prompt(sentence, load_world(world))
    assert reading.groups[0].location == place
    assert reading.groups[0].intent == "wait"


def test_bikes_ridden_through_a_place_are_still_how_people_go():
    reading = read_prompt("Two teens ride through the atrium on bikes.", load_world("mall"))
    assert not reading.unknown_places
    assert reading.groups[0].via == ("main_atrium",)


@pytest.mark.parametrize("sentence", ["Eight residents in wheelchairs queue at the counter for lunch.",
                                      "A dozen patients in wheelchairs line up by the hatch."])
def test_people_in_wheelchairs_are_where_they_line_up(sentence):
    reading = read_prompt(sentence, load_world(REHAB))
    assert reading.groups[0].location == "serving_hatch"
