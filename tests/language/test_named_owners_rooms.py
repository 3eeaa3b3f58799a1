"""A room said as a named person's ("to Priya Shah's office", "Sophie's cabin") is the room the world's
description says is theirs, though no name or alias of it carries the name (language/described_owners.py);
a name the world gives no room is still no place to read."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

NURSERY = "eval/understanding/worlds/day_nursery.yaml"
FESTIVAL = "eval/understanding/worlds/music_festival.yaml"
CONSULATE = "eval/understanding/worlds/consulate.yaml"
OWNED = [
    (NURSERY, "Two parents head to Priya's office.", "nursery_office"),
    (NURSERY, "A parent walks from the lobby to Ms Shah's office.", "nursery_office"),
    (FESTIVAL, "A steward walks from the info point to Sophie Marlow's cabin.", "organiser_cabin"),
    (CONSULATE, "Two clerks walk from the waiting hall to Ingrid Halvorsen's office.", "consul_office"),
]


@pytest.mark.parametrize("world, sentence, place", OWNED)
def test_a_named_persons_room_is_theirs_by_the_description(world, sentence, place):
    reading = read_prompt(sentence, load_world(world))
    assert not reading.unknown_places
    assert reading.groups[0].destination == place


def test_a_name_the_world_gives_no_room_reads_no_room():
    reading = read_prompt("Two parents head to Tom's office.", load_world(NURSERY))
    assert reading.groups[0].destination is None
