"""A chat item that says a place is crowded and gives a bare figure in brackets ("foyer packed (50ish)")
is a crowd of that size there: one more group, not none."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,zone_word,value,others", [
    ("cinema", "foyer packed (50ish), 2 staff at the kiosk, robot idle", "foyer", 50, 1),
    ("ice_rink", "rink heaving (about 80); 3 marshals by the barrier", "rink", 80, 1),
    ("zoo", "cafe busy (25), robot charging", "caf", 25, 0),
])
def test_a_crowded_place_with_a_figure_is_a_crowd_there(read, world, prompt, zone_word, value, others):
    groups = read(world, prompt).groups
    assert len(groups) == 1 + others, groups
    crowd = groups[0]
    assert crowd.count.value == value, crowd
    assert zone_word in (crowd.location or crowd.start or ""), crowd
