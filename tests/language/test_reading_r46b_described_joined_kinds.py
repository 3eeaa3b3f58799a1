"""One count, a word that describes both, then two kinds joined by "and" ("five or six adult sons and
daughters", "eight elderly men and women"): one group of that count, as without the describing word.
Language/joined_kinds.py."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,value", [
    ("hospice", "Four grown-up sons and daughters sit quietly in the relatives' lounge.", 4),
    ("zoo", "Eight elderly men and women stroll from the penguin pool to the cafe.", 8),
    ("mall", "A dozen excited boys and girls run from the toy shop to the food court.", 12),
])
def test_a_described_pair_of_kinds_is_one_group(read, world, prompt, value):
    (g,) = read(world, prompt).groups
    assert g.count.value == value


def test_grown_children_are_no_children(read):
    (g,) = read("hospice", "Four adult sons and daughters sit quietly in the relatives' lounge.").groups
    assert g.label != "child"


def test_two_counted_kinds_stay_two(read):
    assert len(read("zoo", "Three keepers and two vets walk from the penguin pool to the cafe.").groups) == 2
