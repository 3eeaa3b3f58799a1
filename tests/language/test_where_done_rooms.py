"""A place said as where something is done to things ("to where the dinghies are launched", "where the boats
are launched") is the room whose own description says it, not the room that holds the things
(place_where_things, where_rooms.other_room_saying_it)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


@pytest.mark.parametrize("world, sentence, destination", [
    (W + "marina.yaml", "A family wander down from the club bar to where the dinghies are launched.", "slipway"),
    (W + "marina.yaml", "Two lads jog from the car park to where the trailer boats are launched.", "slipway"),
])
def test_where_things_are_handled_is_the_room_saying_so(world, sentence, destination):
    assert read_prompt(sentence, load_world(world)).groups[0].destination == destination


def test_where_things_are_kept_is_still_the_room_holding_them():
    g = read_prompt("Two vergers head over to where the folding tables are stacked.",
                    load_world(W + "cathedral.yaml")).groups[0]
    assert g.destination is not None
