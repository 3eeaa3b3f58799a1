"""A crowd flowing across a space (issue 29): "forty shoppers stream across the food court towards the
exit" starts in the space crossed; a walker crossing it only passes through. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, goal", [
    ("mall", "Forty shoppers stream across the food court towards the exit.", "food_court", "north_exit"),
    ("hospital", "As visiting hours begin, thirty visitors pour across the cafeteria to the pharmacy.",
     "cafeteria", "pharmacy"),
])
def test_a_crowd_flowing_across_a_space_starts_there(read, world, prompt, start, goal):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.start, group.destination) == ("walk", start, goal)


def test_a_walker_crossing_only_passes_through(read):
    group = read("station", "Three backpackers trek across the concourse to the café.").groups[0]
    assert (group.start, group.via, group.destination) == (None, ("concourse",), "cafe")
