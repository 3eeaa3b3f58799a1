"""A stay in a fixture people get into, said before them ("After ten minutes in the sauna, a regular heads
across to the cold plunge", "After a dip in the swimming pool, two guests wander to the bar"): they
start at that fixture, not anywhere in its room. The cause of a hazard said so ("smoke pours from the
gift shop till and the shoppers hurry out") still starts them in the thing's room. Real spaCy, real
worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start", [
    ("day_spa", "After ten minutes in the sauna, a regular heads across to the cold plunge.", "sauna"),
    ("day_spa", "After twenty minutes in the steam room, two friends drift over to the relaxation lounge.", "steam_room"),
    ("swimming_baths", "After a quarter of an hour in the sauna cabin, a swimmer heads back to the changing village.",
     "sauna_cabin"),
    ("hotel", "After a dip in the swimming pool, two guests wander to the bar.", "swimming_pool"),
])
def test_a_fronted_stay_in_a_fixture_is_the_start(read, world, prompt, start):
    assert read(world, prompt).groups[0].start == start


def test_a_hazards_thing_still_starts_them_in_its_room(read):
    group = read("museum", "Smoke pours from the gift shop till and the shoppers hurry out by the main entrance.").groups[0]
    assert group.start == "gift_shop"
