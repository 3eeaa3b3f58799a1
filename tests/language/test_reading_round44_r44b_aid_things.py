"""Round 44 (r44b): walking aids and trolleys named by a person's word ("inches her walker", "with a tartan
shopper", "steers the stroller"): said as someone's own, after "with", or as what a person moves, the
word is the thing, not a second person following the first (language/aid_things.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,destination", [
    ("hospital", "An old man edges his walker from the lobby to the pharmacy.", "pharmacy"),
    ("mall", "A granny with a tartan shopper trundles from the north entrance to the food court.", "food_court"),
    ("care_home", "A resident with a walker shuffles to the lounge.", "lounge"),
    ("museum", "Mr Bell wheels his shopper from the foyer to the cafe.", "cafe"),
    ("museum", "A dad pushing a stroller heads from the foyer to the cafe.", "cafe"),
])
def test_an_aid_said_by_a_persons_word_is_a_thing(read, world, prompt, destination):
    (group,) = read(world, prompt).groups
    assert (group.count.value, group.destination) == (1, destination)


def test_walkers_said_as_people_stay_people(read):
    (group,) = read("city_farm", "Two walkers stroll round the farmyard.").groups
    assert group.count.value == 2
