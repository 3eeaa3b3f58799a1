"""People excepted from everybody keep the place said in their own words, and everybody else does not start
there (language/exception_places.py); "everyone but X" is an exception like "everyone except X"; a device
gathered round is no place to refuse (language/no_place_things.py)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

EXCEPTED = [
    ("hospital", "Everybody except the three nurses in the pharmacy walks to the cafeteria.", "pharmacy", "cafeteria"),
    ("museum", "Everyone but the two guards in the cloakroom heads for the gift shop.", "cloakroom", "gift_shop"),
    ("mall", "Everyone apart from the four cleaners in the food court leaves by the west entrance.", "food_court",
     "west_entrance"),
]
DEVICES = [
    ("station", "Five teenagers huddle round a phone on the concourse.", "concourse"),
    ("residential", "The whole family crowds around the laptop in the living room.", "living_room"),
]


@pytest.mark.parametrize("world, sentence, their_place, destination", EXCEPTED)
def test_the_excepted_stay_where_their_words_say_and_everybody_else_does_not_start_there(
        world, sentence, their_place, destination):
    whole, excepted = read_prompt(sentence, load_world(world)).groups
    assert (whole.intent, whole.destination) == ("walk", destination)
    assert whole.start != their_place
    assert (excepted.intent, excepted.location) == ("wait", their_place)


@pytest.mark.parametrize("world, sentence, place", DEVICES)
def test_a_device_gathered_round_is_no_unknown_place(world, sentence, place):
    reading = read_prompt(sentence, load_world(world))
    assert not reading.unknown_places
    assert reading.groups[0].location == place
