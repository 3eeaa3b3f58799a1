"""A place tallied in chat ("canteen x5, 2 nurses at reception") is so many people at that place
(language/chat_place_tallies.py); a tally of people ("swimmers x10") stays their count."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,counts", [
    ("hospital", "canteen x5, 2 nurses at reception", [5, 2]),
    ("hotel", "lobby x4; 1 concierge at the front desk", [4, 1]),
    ("hotel", "swimmers x10 in the lobby", [10]),
])
def test_chat_place_tally_is_people_there(read, world, prompt, counts):
    reading = read(world, prompt)
    assert sorted(g.count.value for g in reading.groups) == sorted(counts)
    assert all(g.location is not None for g in reading.groups)
