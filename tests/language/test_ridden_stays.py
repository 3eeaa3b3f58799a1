"""A place ridden for a while ("rides the track for ten minutes, then heads off to the cafe") is where
the time is spent, so where they start (language/ridden_stays.py). With no span of time the object of
"ride" is left alone."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("karting_centre", "A teenager rides the track for ten minutes, then heads off to the cafe.", "track", "cafe"),
    ("riding_stables", "A young rider rides the indoor arena for forty minutes, then heads back to the tack room.",
     "indoor_arena", "tack_room"),
    ("karting_centre", "Two lads ride the track for a quarter of an hour and then go to the cafe.", "track", "cafe"),
])
def test_a_place_ridden_for_a_while_is_where_they_start(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.start, g.destination) == (start, destination)
    assert g.wait_seconds is not None


def test_a_ride_with_no_span_names_no_start(read):
    (g,) = read("karting_centre", "A teenager rides the track.").groups
    assert g.start is None
