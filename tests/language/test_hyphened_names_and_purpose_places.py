"""A room named for an age band ("the under-twos room") is that room, no people (language/age_bands.py,
language/noun_heads.py); the place right after a purpose said with "for" is where it is done, so a stay
said before the clause is where they start (language/purpose_places.py)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

NURSERY = "eval/understanding/worlds/day_nursery.yaml"
COMMUNITY = "eval/understanding/worlds/community_centre.yaml"
CLIMBING = "eval/understanding/worlds/climbing_centre.yaml"
BANDED = [
    (NURSERY, "A key worker walks from the under-twos room to the garden.", "baby_room", "garden"),
    (COMMUNITY, "A volunteer walks from the under-fives room to the kitchen.", "playgroup_room", "kitchen"),
]
PURPOSED = [
    (CLIMBING, "After twenty minutes on the bouldering wall, two lads go for a drink in the cafe.", "cafe"),
    (CLIMBING, "Two climbers go for a drink in the cafe.", "cafe"),
    ("residential", "The kids go for a snack in the kitchen.", "kitchen"),
]


@pytest.mark.parametrize("world, sentence, start, destination", BANDED)
def test_a_room_named_for_an_age_band_is_that_room(world, sentence, start, destination):
    reading = read_prompt(sentence, load_world(world))
    assert len(reading.groups) == 1
    assert (reading.groups[0].start, reading.groups[0].destination) == (start, destination)


def test_an_age_band_said_of_people_is_still_people():
    reading = read_prompt("Three under-fives play in the garden.", load_world(NURSERY))
    assert reading.groups[0].count.value == 3 and reading.groups[0].location == "garden"


@pytest.mark.parametrize("world, sentence, destination", PURPOSED)
def test_the_place_after_a_purpose_is_where_they_go(world, sentence, destination):
    group = read_prompt(sentence, load_world(world)).groups[0]
    assert (group.intent, group.destination) == ("walk", destination)


def test_a_stay_before_a_purpose_done_somewhere_is_the_start():
    group = read_prompt("After half an hour on the auto belays, four students go for lunch in the café.",
                        load_world(CLIMBING)).groups[0]
    assert (group.start, group.destination) == ("auto_belays", "cafe")


def test_a_queue_for_something_somewhere_stays_there():
    group = read_prompt("Three commuters queue for tickets at the ticket office.", load_world("station")).groups[0]
    assert (group.intent, group.location) == ("queue", "ticket_office")
