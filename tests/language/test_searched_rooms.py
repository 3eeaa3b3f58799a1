"""A room the world lacks, searched for by name ("looking for the book room") is refused; one the
world has is not (searched_unknown)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


@pytest.mark.parametrize("world, sentence, refused", [
    (W + "bowling_alley.yaml", "Two dads wander out of the arcade searching for the quiet lounge.", "quiet lounge"),
    (W + "aquarium.yaml", "A lost volunteer leaves the cafe looking for the sea horse room.", "sea horse room"),
])
def test_a_room_searched_for_that_the_world_lacks_is_refused(world, sentence, refused):
    assert refused in read_prompt(sentence, load_world(world)).unknown_places


def test_a_room_searched_for_that_the_world_has_is_not_refused():
    reading = read_prompt("A lost volunteer leaves the cafe looking for the education room.",
                          load_world(W + "aquarium.yaml"))
    assert reading.unknown_places == ()
