"""A fronted stay spent watching (waving, looking) from a thing of the world starts the walk at that
thing, named exactly, not at the room around it (participle_stays: "-ing from the X,")."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, destination", [
    ("riding_stables", "After thirty minutes watching from the viewing window, a grandpa heads down to the booking desk.",
     "viewing_window", "booking_desk"),
    ("zoo", "After ten minutes waving from the gift shop till, two kids run to the café.", "shop_till", "cafe"),
    ("library", "After twenty minutes watching from the cafe tables, two mums head to the toilets.", "cafe_tables",
     "toilets"),
])
def test_the_spot_watched_from_is_the_start(read, world, prompt, start, destination):
    g = read(world, prompt).groups[0]
    assert (g.start, g.destination) == (start, destination)
