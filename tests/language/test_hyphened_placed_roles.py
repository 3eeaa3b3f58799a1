"""Round 60 (r60a): a placed role with a hyphened modifier first ("Put a part-time stocktaker by the
bar and ...") is one person placed, not dropped (language/hyphened_modifiers.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,first,second", [
    ("hotel", "Put a part-time stocktaker by the bar and two guests in the lobby.", "bar", "lobby"),
    ("hotel", "Stick a late-shift leafleter at reception and four guests by the bar.", "reception_desk", "bar"),
])
def test_hyphened_role_is_placed(read, world, prompt, first, second):
    groups = read(world, prompt).groups
    assert len(groups) == 2
    assert groups[0].count.value == 1 and groups[0].location == first
    assert groups[1].location == second


def test_supermarket_night_shift_replenisher(read):
    groups = read("supermarket", "Put a night-shift replenisher in the freezer section and three shoppers at the "
                                 "cake counter.").groups
    assert [g.count.value for g in groups] == [1, 3]
