"""A verb the lexicon does not know, followed by "out of" a place, is going out of it (language/groups.py
`_default_intent`): "stumble / stagger / tumble out of X" walks from X, not waits there."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

OUT_OF = [
    ("hospital", "Two dazed patients stumble out of radiology.", "radiology"),
    ("hospital", "A porter lurches out of the pharmacy.", "pharmacy"),
    ("station", "Three drunk lads stagger out of the cafe.", "cafe"),
]


@pytest.mark.parametrize("world, sentence, start", OUT_OF)
def test_an_unknown_verb_out_of_a_place_leaves_it(world, sentence, start):
    group = read_prompt(sentence, load_world(world)).groups[0]
    assert (group.intent, group.start) == ("walk", start)


def test_out_of_breath_is_no_going_out():
    group = read_prompt("Two nurses out of breath wait in the cafeteria.", load_world("hospital")).groups[0]
    assert (group.intent, group.location) == ("wait", "cafeteria")


@pytest.mark.parametrize("world, sentence, door", [
    ("residential", "Grandad stomps out the back door in a huff.", "back_door"),
    ("office", "The sacked temp storms out the main entrance.", "main_entrance"),
])
def test_an_unknown_verb_out_a_door_goes_through_it(world, sentence, door):
    group = read_prompt(sentence, load_world(world)).groups[0]
    assert (group.intent, group.destination) == ("walk", door)


def test_a_chore_out_a_room_stays_there():
    group = read_prompt("Two cleaners are scrubbing out the kitchen.", load_world("office")).groups[0]
    assert group.intent != "walk" and group.location == "kitchen"


def test_people_said_with_including_are_members_not_a_group():
    groups = read_prompt("A family of five including two grandparents waits at gate A1.", load_world("airport")).groups
    assert [(g.label, g.count.value) for g in groups] == [("family", 5)]
