"""A crowd said as an army or a legion ("an army of shoppers", "a legion of fans") is a collective
of its members, many and vague, and a count set off by commas ("sixty in all", "some fifty of them")
is their number (language/lexicon.py: IMPLIED_RANGES, QUANTIFYING_COLLECTIVES)."""

from __future__ import annotations

import pytest

CASES = [
    ("mall", "An army of shoppers, forty in all, surges from the car park into the food court.", "shopper",
     "exact", 40),
    ("stadium", "A legion of fans, some fifty of them, streams out of the north stand.", "fan", "approximate", 50),
    ("station", "A noisy army of commuters, thirty in all, waits on platform 2.", "commuter", "exact", 30),
]


@pytest.mark.parametrize("world,prompt,label,kind,value", CASES)
def test_the_apposed_count_is_the_armys(read, world, prompt, label, kind, value):
    (group,) = read(world, prompt).groups
    assert group.label == label and (group.count.kind, group.count.value) == (kind, value)


def test_an_army_without_a_count_is_many_and_an_army_officer_one(read):
    (shoppers,) = read("mall", "An army of shoppers surges into the food court.").groups
    assert shoppers.label == "shopper" and shoppers.count.kind == "vague" and shoppers.count.low >= 15
    (officer,) = read("stadium", "An army officer walks to the north stand.").groups
    assert officer.count.value == 1
