"""Two kinds of people said as one ("a handful of mums and dads", "boys and girls"): one group."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,low,high", [
    ("cinema", "A few lads and lasses hang about by the popcorn stand.", 2, 6),
    ("aquarium", "A handful of grandmas and grandpas sit on the benches by the shark tunnel.", 3, 6),
    ("library", "Several husbands and wives browse the shelves in the reading room.", 3, 8),
])
def test_a_quantifier_before_two_joined_kinds_counts_both(read, world, prompt, low, high):
    groups = read(world, prompt).groups
    assert len(groups) == 1, groups
    assert low <= groups[0].count.value <= high, groups[0]


@pytest.mark.parametrize("world,prompt", [
    ("museum", "Boys and girls crowd round the dinosaur skeleton while a guard stands by the door."),
    ("zoo", "Mums and dads queue at the ice cream kiosk while a guard waits by the main gate."),
])
def test_the_halves_of_one_people_are_one_group(read, world, prompt):
    groups = read(world, prompt).groups
    assert len(groups) == 2, groups
    assert groups[1].count.value == 1, groups


def test_two_kinds_each_counted_stay_two_groups(read):
    groups = read("hospital", "Two nurses and three doctors walk to the cafeteria.").groups
    assert [g.count.value for g in groups] == [2, 3], groups
