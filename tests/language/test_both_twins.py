"""Round 52 (r52a): "both twins", "the two twins" are the one pair, two people, not two pairs of
twins (language/collectives.py); "both X" is two."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("residential", "Both twins are brushing their teeth in the bathroom."),
    ("residential", "Dad dozes on the sofa while the two twins play in the bathroom."),
    ("hotel", "Both twins wait by the bar."),
])
def test_both_twins_are_two_people(read, world, prompt):
    groups = read(world, prompt).groups
    assert groups[-1].count.value == 2


def test_both_guards_are_two(read):
    (group,) = read("hotel", "Both guards wait by the bar.").groups
    assert group.count.value == 2
