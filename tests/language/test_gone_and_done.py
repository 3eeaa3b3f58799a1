"""Going and doing something in a place is going there: "go and flop in the café seating",
"went and sat in the games room" (gone_and_done); "go and wait in X" stays a wait at X."""

from __future__ import annotations

import pytest

from grove_tui.language.gone_and_done import as_gone_to
from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


@pytest.mark.parametrize("world, sentence, destination", [
    (W + "hotel.yaml", "Two weary guests go and collapse on the lobby sofas.", "lobby_sofas"),
    (W + "student_union.yaml", "After the lecture, four freshers went and sat in the games room.", "games_room"),
    (W + "library.yaml", "A pair of sixth-formers go and hide in the reading room.", "reading_room"),
])
def test_going_and_doing_in_a_place_is_going_there(world, sentence, destination):
    group = read_prompt(sentence, load_world(world)).groups[0]
    assert group.destination == destination


def test_a_wait_or_queue_said_after_going_is_left_alone():
    assert as_gone_to("they go and queue at the bar") == "they go and queue at the bar"
    assert as_gone_to("she goes and sits down in the cafe") == "she goes to the cafe"
