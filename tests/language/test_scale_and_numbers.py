"""Round 60 (r60a): a scale word with its tail after "and" is one number ("the hundred and twenty or
so", "two hundred and fifty"), not the tail alone (language/scale_and_figures.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,value", [
    ("hotel", "The hundred and forty or so guests wait by the bar.", 140),
    ("hotel", "Two hundred and thirty-five guests wait by the bar.", 235),
    ("hotel", "About a hundred and ten guests wait by the bar.", 110),
    ("supermarket", "When the alarm sounds, the three hundred and sixty or so shoppers leave the store.", 360),
])
def test_scale_and_tail_is_one_number(read, world, prompt, value):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    assert groups[0].count.value == value


def test_call_floor_hundred_and_twenty(read):
    (group,) = read("call_centre", "Mid-shift the alarm goes, and the hundred and twenty or so agents on the call "
                                   "floor pour out of the west exit.").groups
    assert group.count.value == 120 and group.count.kind == "approximate"
