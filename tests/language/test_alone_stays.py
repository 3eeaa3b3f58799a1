"""A fronted stay with a word of manner before its place (issue 29): "After half an hour alone in the
cafeteria, ..." is a wait that long at that place, where they start. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, goal, seconds", [
    ("hospital", "After half an hour alone in the cafeteria, a porter heads back to the main entrance.",
     "cafeteria", "main_entrance", 1800),
    ("office", "After an hour together at the reception desk, two temps wander over to the kitchen.",
     "reception_desk", "kitchen", 3600),
    ("library", "After ten minutes alone sat in the quiet room, a student pops down to the café.",
     "reading_room", "cafe", 600),
])
def test_a_stay_alone_somewhere_is_a_wait_there(read, world, prompt, start, goal, seconds):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.start, group.destination) == ("walk", start, goal)
    assert group.wait_seconds == seconds


def test_alone_without_a_place_is_no_stay(read):
    group = read("hospital", "After twenty minutes alone, a porter heads back to the main entrance.").groups[0]
    assert group.wait_seconds is None
