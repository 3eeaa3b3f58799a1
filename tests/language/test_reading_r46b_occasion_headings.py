"""An occasion heading a chat line, named by whose it is ("kids bday: 9 on the wall + 3 parents on the
bench"): the heading's people are the ones its items count, no group of their own.
Language/occasion_headings.py."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,labels", [
    ("zoo", "kids party: 12 at the penguin pool + 2 mums in the cafe", ("kid", "mum")),
    ("bowling_alley", "teens bday - 8 on the lanes, 3 dads at the bar", ("teen", "dad")),
    ("mall", "pensioners outing: 15 in the food court", ("pensioner",)),
])
def test_heading_people_are_the_counted_ones(read, world, prompt, labels):
    groups = read(world, prompt).groups
    assert len(groups) == len(labels)
    assert groups[0].count.kind == "exact"


def test_a_heading_of_other_people_stays(read):
    assert len(read("hospital", "nurses: 3 porters in the cafeteria").groups) == 2
