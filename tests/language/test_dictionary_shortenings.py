"""Round 52 (r52c): a chat shortening alone is put right only when it is no dictionary word. "the pub"
is a pub, not the "public toilets" it starts; "at recep" is still the reception (language/spelling.py,
parser.dictionary_word)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("bus_station", "Three drivers leave the canteen and walk to the pub."),
    ("county_show", "A farmer walks from the pub to the show ring."),
])
def test_a_dictionary_word_is_not_a_shortened_name(read, world, prompt):
    reading = read(world, prompt)
    assert not any("'pub'" in c for c in reading.corrections)
    assert "pub" in reading.unknown_places


@pytest.mark.parametrize("world,prompt,place", [
    ("tennis_club", "Two members wait at recep for their coach.", "foyer"),
    ("zoo", "Four teenagers queue at the caf for ice cream.", "cafe"),
])
def test_a_chat_shortening_is_still_put_right(read, world, prompt, place):
    reading = read(world, prompt)
    assert place in reading.places


def test_a_word_whose_ending_makes_the_name_is_still_read(read):
    reading = read("casino", "Fresh from a smoke, a pair of croupiers cut across from the poker lounge to the "
                   "roulette wheel.")
    assert not reading.unknown_places
    assert [g.intent for g in reading.groups] == ["walk"]
