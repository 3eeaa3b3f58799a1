"""What people ride or float on as they go ("on rubber rings", "on a wooden horse") is how they go, no
place: never the world's rack of floats or its carousel (ridden_things.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, sentence, not_read", [
    ("swimming_baths", "Two toddlers paddle across the learner pool on floats while the robot waits in the reception.",
     "float_store"),
    ("seaside_pier", "A toddler rides along the boardwalk on a wooden horse while the robot waits at the entrance.",
     "carousel"),
])
def test_ridden_thing_is_no_place(read, world, sentence, not_read):
    g = read(world, sentence).groups[0]
    assert not_read not in (g.start, g.destination, g.location)


def test_riders_stay_where_they_drift(read):
    g = read("water_park", "While half a dozen kids drift round the lazy river on rubber rings, the robot takes a tray "
                           "of slushies from the café counter out to the sun terrace.").groups[0]
    assert g.location == "lazy_river"
