"""A feeling fronted before a length of stay ("Restless after an hour in the food court, a teenager
drifts over to X"): a wait of that length at the place first, then the move (fronted_feeling_waits.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start,seconds", [
    ("hospital", "Bored after twenty minutes in the canteen, two porters wander off to the main entrance.",
     "cafeteria", 1200),
    ("mall", "Restless after an hour in the food court, a teenager drifts over to the cinema.", "food_court", 3600),
    ("office", "Tired after forty minutes at the photocopier, an intern trudges back to the kitchen.", "printer", 2400),
])
def test_a_feeling_before_after_n_minutes_in_a_place_is_a_wait_there_first(read, world, prompt, start, seconds):
    group = read(world, prompt).groups[0]
    assert (group.start, group.wait_seconds) == (start, seconds)
