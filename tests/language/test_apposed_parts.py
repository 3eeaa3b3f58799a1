"""Part of a counted group said between commas with what sets it apart (round 71): "twenty commuters, five
with bikes, wait ...": the five are part of the twenty, not five more."""

from __future__ import annotations

import pytest

CASES = [
    ("station", "Twenty commuters, five with bikes, wait on platform 2.", 20, 5),
    ("primary_school", "A dozen pupils, one on crutches, walk to the school hall.", 12, 1),
    ("airport", "6 travellers, 2 pushing trolleys, head to check-in.", 6, 2),
]


@pytest.mark.parametrize(("world", "prompt", "whole", "part"), CASES)
def test_the_part_is_a_subset(read, world, prompt, whole, part):
    groups = read(world, prompt).groups
    assert groups[0].count.value == whole
    assert all(g.relation == "subset_of:0" for g in groups[1:])
    assert sum(g.count.value or 0 for g in groups[1:]) in (0, part)


def test_a_larger_number_is_no_part(read):
    groups = read("station", "Two guards, ten in the queue, wait on platform 2.").groups
    assert all(g.relation != "subset_of:0" or (g.count.value or 0) < 2 for g in groups)
