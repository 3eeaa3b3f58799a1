"""A place swamped, mobbed or invaded by people coming from somewhere is where they go (swamped_places);
people who come from nowhere said stay where the place is."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


@pytest.mark.parametrize("world, sentence, start, destination", [
    (W + "bus_station.yaml", "The cafe gets mobbed by a crowd of students streaming in from the concourse.",
     "concourse", "cafe"),
    (W + "campsite.yaml", "The camp shop is invaded by six kids racing over from the playground.",
     "playground", "camp_shop"),
])
def test_a_crowded_place_is_where_people_coming_from_elsewhere_go(world, sentence, start, destination):
    g = read_prompt(sentence, load_world(world)).groups[0]
    assert (g.intent, g.start, g.destination) == ("walk", start, destination)


def test_people_crowding_a_place_from_nowhere_said_stay_there():
    g = read_prompt("The camp shop is swamped by six kids wanting ice creams.", load_world(W + "campsite.yaml")).groups[0]
    assert g.location == "camp_shop" and g.destination is None
