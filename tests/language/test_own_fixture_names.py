"""A fixture called by its own whole name beats the room that has that name only as an alias: "the
hitting wall", "the grand staircase", "the trade desk" (own_fixture_names); the room's own name stays
the room."""

from __future__ import annotations

import pytest

from grove_tui.language.places import place_index
from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


@pytest.mark.parametrize("world, sentence, location", [
    (W + "bingo_hall.yaml", "Two old friends wait at the grand staircase for the doors to open.", "grand_staircase"),
    (W + "tennis_club.yaml", "A junior member lingers by the hitting wall after her lesson.", "hitting_wall"),
])
def test_a_fixture_said_by_its_own_name_is_the_fixture(world, sentence, location):
    assert read_prompt(sentence, load_world(world)).groups[0].location == location


def test_the_room_said_by_its_own_name_stays_the_room():
    index = place_index(load_world(W + "bingo_hall.yaml"))
    assert index.match(("stair", "hall")).name == "stair_hall"
    assert index.match(("grand", "staircase")).name == "grand_staircase"
