"""Round 56 (r56a): chat items joined by "+" or "&" whose second count is "~N" ("2 porters by the lifts +
~15 guests in the bar") are two groups; the "~" is read as "about" before the items are joined
(language/text.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,counts", [
    ("hospital", "3 nurses @ reception + ~20 visitors in the canteen, robot waits", [3, 20]),
    ("station", "~5 cleaners on the concourse & ~30 commuters @ platform 2", [5, 30]),
    ("hotel", "2 porters by the lifts + ~ 15 guests in the bar", [2, 15]),
])
def test_an_about_count_after_a_joining_sign_is_a_second_group(read, world, prompt, counts):
    reading = read(world, prompt)
    assert [g.count.value for g in reading.groups] == counts
    assert reading.groups[-1].count.kind == "approximate"
