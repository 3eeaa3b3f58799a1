"""Chat's "4" for "for" before a plural that ends an item of a chat list ("queuin 4 scales, 3 more ..."),
not only the prompt: "queueing for X" is queueing at X. A "4" before people ("4 nurses") or after a word a
place is numbered by stays a count. Real spaCy, understanding worlds, no model."""

from __future__ import annotations

from functools import cache

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.language.text import normalise
from grove_tui.world.loader import load_world
from grove_tui.world.model import World


@cache
def _world(name: str) -> World:
    return load_world(f"eval/understanding/worlds/{name}.yaml")


CASES = [
    ("casino", "3 guests queuin 4 toilets, 2 more at the cloakroom counter", 3, "toilets"),
    ("vet_hospital", "2 owners waitin 4 scales, 1 more in reception", 2, "dog_scales"),
    ("dialysis_unit", "6 pts queuin 4 scales, 3 more slumped in waiting rm", 6, "weighing_scales"),
]


@pytest.mark.parametrize(("world", "sentence", "count", "location"), CASES)
def test_chat_for_before_a_comma(world: str, sentence: str, count: int, location: str) -> None:
    reading = read_prompt(sentence, _world(world))
    assert len(reading.groups) == 2, reading.groups
    first = reading.groups[0]
    assert first.count.value == count
    assert first.location == location


@pytest.mark.parametrize("text", ["staff waiting at till 4 tills, 2 more", "a family with 4 bags, 2 more",
                                  "supervisor calls 4 nurses, then leaves"])
def test_a_count_stays_a_count(text: str) -> None:
    assert " for " not in normalise(text)
