"""A count, a describing word, a hyphened modifier, then a plural no lexicon lists as people ("forty
grumbling season-ticket holders") is that many people (language/people.py, person_head)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

CASES = [
    ("station", "Forty grumbling season-ticket holders walk to the ticket office.", 40),
    ("mall", "Twelve chattering gift-card holders queue at the information desk.", 12),
    ("hospital", "Eight muttering day-pass holders wait in the cafeteria.", 8),
]


@pytest.mark.parametrize("world, sentence, n", CASES)
def test_the_described_hyphened_plural_keeps_its_count(world, sentence, n):
    group, = read_prompt(sentence, load_world(world)).groups
    assert group.count.value == n
