"""Round 52 (r52a): a "-side" word after people ("2 physios poolside", "2 nurses bedside") is where
they are, by the place its first half names, also as the second item of a chat list
(language/side_places.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,place", [
    ("physio_clinic", "Three patients wait in the gym, two physios poolside.", "hydrotherapy_pool"),
    ("hospital", "4 visitors in reception, 2 nurses bedside", "ward_a_bed_1"),
])
def test_a_side_word_places_the_second_group(read, world, prompt, place):
    groups = read(world, prompt).groups
    assert len(groups) == 2
    assert groups[1].count.value == 2 and groups[1].location == place


def test_a_lone_side_word_places_people(read):
    (group,) = read("physio_clinic", "2 physios poolside").groups
    assert group.count.value == 2 and group.location == "hydrotherapy_pool"
