"""A room said for the people in it ("all of the circle, roughly 300 punters, escapes", "the whole of the
stalls, some 500 fans, leaves", "all of screen 1"): the room is where they start when they go, and where
they stay when they stay. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start", [
    ("concert_venue", "Smoke drifts across the upper tier in the second half, and all of the circle, roughly 300 "
                      "punters, escapes via the circle exit.", "circle"),
    ("concert_venue", "The whole of the stalls, some 500 fans, leaves by the main doors.", "stalls"),
    ("cinema", "All of screen 1, forty or so people, files out through the fire exit.", "screen_1"),
])
def test_the_whole_room_starts_in_it(read, world, prompt, start):
    group = read(world, prompt).groups[0]
    assert group.start == start
    assert start not in group.via


def test_the_whole_room_staying_stays_in_it(read):
    assert read("office", "All of the boardroom waits for the CEO.").groups[0].location == "boardroom"
