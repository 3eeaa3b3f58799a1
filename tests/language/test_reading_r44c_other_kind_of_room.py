"""A room the world knows by a bare word for its kind ("shop" of a station's newsagent), said with a word
before it that makes it another kind of room: "the bike shop" is no newsagent, and a world without one
refuses it. A word of the room's own kind ("the paper shop", "the village shop") still names it. Real
spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, refused", [
    ("station", "A pair of backpackers haul their rucksacks out of the waiting room to the bike shop.", "bike shop"),
    ("ferry_terminal", "Two cyclists wheel their bikes from the cafe to the bike shop.", "bike shop"),
    ("post_office", "A pensioner shuffles from the counters to the flower shop.", "flower shop"),
])
def test_another_kind_of_shop_is_refused(read, world, prompt, refused):
    assert refused in read(world, prompt).unknown_places


@pytest.mark.parametrize("world, prompt, destination", [
    ("ferry_terminal", "A lorry driver strolls from the cafe to the paper shop.", "travel_shop"),
    ("post_office", "A pensioner shuffles from the counters to the stationery shop.", "card_shop"),
    ("city_farm", "Two volunteers walk from the cafe to the village shop.", "farm_shop"),
    ("garden_centre", "A couple wander from the cafe to the pet shop.", "pet_aquatics"),
])
def test_a_word_of_the_rooms_own_kind_still_names_it(read, world, prompt, destination):
    reading = read(world, prompt)
    assert reading.unknown_places == ()
    assert reading.groups[0].destination == destination
