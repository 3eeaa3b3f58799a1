"""A misspelt count word before "of" ("a cuple of", "a handfull of", "a coupla") is read as spelt right."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,low,high", [
    ("airport", "a cuple of pilots waitng by the gate B2 desk", 2, 2),
    ("hospital", "a coupla porters hang about by the pharmacy", 2, 2),
    ("library", "A handfull of students wait at the issue desk.", 3, 6),
    ("zoo", "a dozne of schoolkids queue at the ice cream kiosk", 12, 12),
])
def test_a_misspelt_count_word_counts(read, world, prompt, low, high):
    groups = read(world, prompt).groups
    assert len(groups) == 1, groups
    assert low <= groups[0].count.value <= high, groups[0]
