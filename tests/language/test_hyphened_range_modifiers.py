"""A hyphened modifier ending in a collective word ("early-shift", "late-shift") before a plural person
noun names their kind; the count before it stays exact (language/person_modifiers.py)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

CASES = [
    ("hospital", "Six early-shift porters walk to the pharmacy.", 6),
    ("hospital", "Three late-shift cleaners wait in the cafeteria.", 3),
    ("airport", "Seven first-class travellers queue at gate A1.", 7),
    ("mall", "Two day-shift guards stroll to the food court.", 2),
]


@pytest.mark.parametrize("world, sentence, n", CASES)
def test_the_count_before_a_hyphened_modifier_is_exact(world, sentence, n):
    group, = read_prompt(sentence, load_world(world)).groups
    assert (group.count.kind, group.count.value) == ("exact", n)
