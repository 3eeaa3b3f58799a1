"""Round 52 (r52a): an opening "Have X at A and Y doing B" places a short role said with a noun
before it ("a mall cop", "a lab tech") as its own person, beside the second group
(language/placed_people.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,first,second", [
    ("hospital", "Have a lab tech at the pharmacy and three patients waiting in reception.", "pharmacy", 3),
    ("mall", "Have a mall cop by the fountain and two shoppers waiting at the bookshop.", "fountain", 2),
    ("mall", "Have a cop next to the fountain and a pair of teenagers hanging about in the bookshop.", "fountain", 2),
])
def test_have_lists_a_short_role_and_a_second_group(read, world, prompt, first, second):
    groups = read(world, prompt).groups
    assert len(groups) == 2
    assert groups[0].count.value == 1 and groups[0].location == first
    assert groups[1].count.value == second


def test_have_places_a_lone_short_role(read):
    (group,) = read("mall", "Have a cop next to the fountain.").groups
    assert group.count.value == 1 and group.location == "fountain"
