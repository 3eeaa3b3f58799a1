"""Chat short forms of the words places are named by ("tbl", "rm", "mtg", "dept") are written out before
the prompt is parsed, so "4 ppl @ the snack tbl" reads the snack table entity and "the large mtg rm" the
large meeting room; a table in a named room is that room's table. Real spaCy, shipped and understanding
worlds, no model."""

from __future__ import annotations

from functools import cache

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world.loader import load_world
from grove_tui.world.model import World


@cache
def _world(name: str) -> World:
    return load_world(name)


CASES = [
    ("eval/understanding/worlds/blood_donor_centre.yaml", "3 donors @ the snack tbl", 3, "snack_table"),
    ("eval/understanding/worlds/art_gallery.yaml", "2 curators @ back office tbl", 2, "office_meeting_table"),
    ("office", "3 devs in the large mtg rm", 3, "boardroom"),
    ("office", "2 ppl @ kitchen tbl", 2, "kitchen_table"),
]


@pytest.mark.parametrize(("world", "sentence", "count", "location"), CASES)
def test_chat_place_words(world: str, sentence: str, count: int, location: str) -> None:
    reading = read_prompt(sentence, _world(world))
    assert len(reading.groups) == 1, reading.groups
    group = reading.groups[0]
    assert group.count.value == count
    assert group.location == location
