"""The verb of a purpose ("to sign for", "in to collect") is no place to read or refuse (issue 29).
Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, goal", [
    ("hospital", "A porter strolls over to the pharmacy to sign for a crate of saline.", "pharmacy"),
    ("mall", "Two cleaners wander round to the food court to wipe down the tables.", "food_court"),
    ("furniture_store", "A driver walks from the car park in to fetch a flat-pack wardrobe.", None),
])
def test_the_verb_of_a_purpose_is_no_unknown_place(read, world, prompt, goal):
    reading = read(world, prompt)
    assert reading.unknown_places == ()
    if goal is not None:
        assert reading.groups[0].destination == goal


def test_an_unknown_place_after_to_is_still_refused(read):
    assert read("hospital", "Three visitors walk to the bowling alley.").unknown_places != ()


def test_a_place_word_the_parser_reads_as_a_verb_is_still_a_place(read):
    assert read("airport", "Nine passengers walk to gate Q12.").unknown_places != ()
