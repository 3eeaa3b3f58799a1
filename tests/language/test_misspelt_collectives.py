"""A collective misspelt before "of" and its size ("a famly of five", "a partty of six", "a faimly of
three") is the collective spelt right, counted by its size (language/count_spelling.py)."""

from __future__ import annotations

import pytest

CASES = [
    ("mall", "A famly of five walks from the food court to the bookshop.", "family", 5),
    ("hospital", "A partty of six waits in the cafeteria.", "party", 6),
    ("station", "A faimly of three waits on platform 2.", "family", 3),
]


@pytest.mark.parametrize("world,prompt,label,value", CASES)
def test_the_misspelt_collective_counts_its_size(read, world, prompt, label, value):
    (group,) = read(world, prompt).groups
    assert group.label == label and (group.count.kind, group.count.value) == ("exact", value)
