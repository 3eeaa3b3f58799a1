"""Food said by a verb of eating into it ("tucking into lasagne", "bites into a samosa", "gets stuck into a
fry-up") is no place to refuse; a room after "into" ("tucks into a corner of the gym") is still a place.
Real spaCy, real worlds and the eval worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, zone", [
    ("hospital", "Three porters are tucking into lasagne in the cafeteria.", "cafeteria"),
    ("office", "Two interns bite into samosas in the kitchen.", "kitchen"),
    ("fire_station", "A crew of four get stuck into a fry-up in the mess.", "mess_room"),
    ("county_show", "Have six farmers tucking into hog roast at the food hall.", None),
])
def test_food_eaten_into_is_no_place(read, world, prompt, zone):
    reading = read(world, prompt)
    assert reading.unknown_places == ()
    if zone is not None:
        assert reading.groups[0].location == zone


def test_a_room_tucked_into_is_still_a_place(read):
    assert read("hospital", "A nurse tucks into a corner of the gym.").unknown_places
