"""A wait that lasts until something happens, then a move, sets off from where they waited
("sits in reception till the manager comes, then goes to the boardroom"): waits_until."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world


@pytest.mark.parametrize("world, sentence, start, destination", [
    ("worlds/office.yaml", "A visitor sits in reception till the manager comes, then goes to the boardroom.",
     "reception", "boardroom"),
    ("worlds/mall.yaml", "A mother waits at the pharmacy until her prescription is ready and then goes to the "
     "supermarket.", "pharmacy", "supermarket"),
    ("worlds/hospital.yaml", "Two visitors sit in the main waiting room until the doctor calls them, then walk "
     "to exam room 2.", "main_waiting_room", "exam_room_2"),
])
def test_a_wait_until_an_event_then_a_move_starts_where_they_waited(world, sentence, start, destination):
    group = read_prompt(sentence, load_world(world)).groups[0]
    assert group.intent == "wait"
    assert (group.start, group.location, group.destination) == (start, start, destination)


def test_a_wait_until_an_event_alone_has_no_start():
    group = read_prompt("Three passengers wait at gate a2 until boarding starts.", load_world("worlds/airport.yaml")).groups[0]
    assert (group.start, group.location, group.destination) == (None, "gate_a2", None)
