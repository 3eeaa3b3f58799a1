"""A kind of place said on the head of one of the world's own kinds ("the diving pool" where the pools are
the wave pool and the splash pool) is a place the world lacks, refused; a synonym is not (sibling_kinds.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, sentence, refused", [
    ("community_centre", "Two kids wander from the foyer over to the music room.", "music room"),
    ("county_show", "A couple stroll from the grand ring across to the dog tent.", "dog tent"),
    ("water_park", "Three dads carry their towels from the sun terrace towards the diving pool.", "diving pool"),
])
def test_sibling_kind_is_refused(read, world, sentence, refused):
    assert refused in read(world, sentence).unknown_places


@pytest.mark.parametrize("world, sentence, destination", [
    ("water_park", "Two girls walk from the changing village to the swimming pool.", "wave_pool"),
    ("community_centre", "Two tutors walk from the foyer to the large meeting room.", "oak_room"),
    ("county_show", "A couple stroll from the grand ring across to the food tent.", "food_hall"),
])
def test_own_kind_is_read(read, world, sentence, destination):
    r = read(world, sentence)
    assert r.unknown_places == () and r.groups[0].destination == destination
