"""A verb of going the parser reads as a noun ends who people are from (language/who_from.py); a place
refused after "rather than"/"instead of" ends the purpose before it (sentence.py) and its people word is
no group (language/cue_in_names.py); a stopword that starts a place's name is part of it, so the world's
lacking the place is refused (language/tokens.py)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

BREWERY = "eval/understanding/worlds/brewery.yaml"
FROM_THEN_VERB = [
    ("museum", "Eight walkers from a rambling club file into the gift shop.", "destination", "gift_shop"),
    ("hospital", "Twelve nurses from an agency file past the pharmacy.", "via", ("pharmacy",)),
    ("museum", "Thirty pupils from a village school file out of the cafe.", "start", "cafe"),
]
NEGATED = [
    ("station", "Two guards head to the ticket office rather than the staff lounge.", "ticket_office", None),
    ("station", "Two guards go to the cafe for tea rather than the staff lounge.", "cafe", "for tea"),
    ("office", "Three developers go to the kitchen for snacks instead of the meeting room.", "kitchen", "for snacks"),
    ("mall", "A couple head to the food court for lunch rather than the cinema.", "food_court", "for lunch"),
]


@pytest.mark.parametrize("world, sentence, role, place", FROM_THEN_VERB)
def test_a_verb_read_as_a_noun_is_no_part_of_where_they_are_from(world, sentence, role, place):
    reading = read_prompt(sentence, load_world(world))
    assert not reading.unknown_places
    assert getattr(reading.groups[0], role) == place


@pytest.mark.parametrize("world, sentence, destination, purpose", NEGATED)
def test_a_place_not_gone_to_is_neither_purpose_nor_people(world, sentence, destination, purpose):
    reading = read_prompt(sentence, load_world(world))
    assert len(reading.groups) == 1
    group = reading.groups[0]
    assert (group.intent, group.destination, group.purpose) == ("walk", destination, purpose)


@pytest.mark.parametrize("sentence", ["Two brewers walk over to the still house.",
                                      "A guide takes six tourists from the tap room to the still house."])
def test_a_place_named_with_a_stopword_the_world_lacks_is_refused(sentence):
    reading = read_prompt(sentence, load_world(BREWERY))
    assert any(u.startswith("still ") for u in reading.unknown_places)


def test_still_as_an_adverb_is_no_place():
    reading = read_prompt("Two brewers are still in the brewhouse.", load_world(BREWERY))
    assert not reading.unknown_places
    assert reading.groups[0].location == "brewhouse"
