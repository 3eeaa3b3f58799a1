"""A crowd that pours through a room and then goes on starts in that room (poured_through); a walk
through a room to somewhere keeps it as the way."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


@pytest.mark.parametrize("world, sentence, start, destination", [
    (W + "student_union.yaml", "Around forty freshers stream through the foyer and head for the bar.", "foyer", "bar"),
    (W + "aquarium.yaml", "A school party of thirty floods through the ticket hall and makes for the gift shop.",
     "ticket_hall", "gift_shop"),
])
def test_poured_through_a_room_then_going_on_starts_there(world, sentence, start, destination):
    group = read_prompt(sentence, load_world(world)).groups[0]
    assert (group.start, group.destination) == (start, destination)
