"""A kind of room said with a hyphened word ("in search of a first-aid room") that the world lacks is
refused as written; one the world has under that name is not (searched_unknown, round 72)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


@pytest.mark.parametrize("world, sentence, refused", [
    (W + "aquarium.yaml", "A lost volunteer leaves the cafe looking for a first-aid room.", "first-aid room"),
    (W + "bowling_alley.yaml", "Two dads wander out of the arcade in search of a multi-faith room.", "multi-faith room"),
])
def test_a_hyphened_kind_of_room_the_world_lacks_is_refused(world, sentence, refused):
    assert refused in read_prompt(sentence, load_world(world)).unknown_places


def test_a_hyphened_kind_of_room_the_world_has_is_not_refused():
    reading = read_prompt("Two visitors slip out of the lounge in search of a multi-faith room.",
                          load_world(W + "hospice.yaml"))
    assert reading.unknown_places == ()
