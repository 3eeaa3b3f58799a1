"""A fronted stay said by what was done and where (issue 29): "After forty minutes of silent study in the
quiet room, ..." is a wait that long at that place, where they start. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, goal, seconds", [
    ("office", "After an hour of paperwork at the reception desk, a temp wanders over to the kitchen.",
     "reception_desk", "kitchen", 3600),
    ("hospital", "After twenty minutes of small talk in the cafeteria, two porters head back to the main entrance.",
     "cafeteria", "main_entrance", 1200),
    ("library", "After forty minutes of silent study in the quiet room, a doctoral candidate pops down to the café "
     "for a latte.", "reading_room", "cafe", 2400),
])
def test_a_fronted_stay_of_doing_somewhere_is_a_wait_there(read, world, prompt, start, goal, seconds):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.start, group.destination) == ("walk", start, goal)
    assert group.wait_seconds == seconds


def test_a_length_alone_is_no_stay(read):
    group = read("hospital", "After twenty minutes, two porters head back to the main entrance.").groups[0]
    assert group.wait_seconds is None
