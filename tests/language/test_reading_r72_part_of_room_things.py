"""Round 72: a thing placed at a part of a room ("the tables at the back of the party room") is that
room's thing of that kind, not one of the kind elsewhere (place_landmark)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


@pytest.mark.parametrize("world, sentence, place", [
    ("climbing_centre", "A mum walks from the bouldering hall to the tables at the back of the party room.", "party_tables"),
    ("ferry_terminal", "An old man walks from the cafe to the chairs at the back of the prayer room.", "prayer_room_chairs"),
])
def test_a_thing_at_a_part_of_a_room_is_that_rooms(world, sentence, place):
    assert read_prompt(sentence, load_world(W + world + ".yaml")).groups[0].destination == place
