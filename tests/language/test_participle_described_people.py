"""A count, then an "-ing" word, then people ("two whining toddlers", "three giggling teenagers") is the people,
described by what they are doing: not a bare count of people doing it (language/chat_fragments.py), and not lost
after a verb of taking (language/people.py). A gathering "for" which people come is no place to refuse
(language/not_places.py)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

DESCRIBED = [
    ("hospital", "Three coughing pensioners shuffle from the main waiting room to the pharmacy.", "pensioner", 3),
    ("museum", "Two yawning students trail from the great hall to the cafe.", "student", 2),
    ("station", "Four chattering schoolgirls run from the ticket hall to the cafe.", "schoolgirl", 4),
]
TAKEN = [
    ("residential", "Mum drags two whining toddlers from the kitchen to the bathroom.", "toddler", 2),
    ("mall", "A mother drags two whining toddlers out of the toy store towards the exit.", "toddler", 2),
]
EVENTS = [
    ("museum", "Dozens of families pour in through the main entrance for the half-term fair."),
    ("station", "Commuters drift into the concourse for the charity bake sale."),
]


@pytest.mark.parametrize("world, sentence, label, count", DESCRIBED)
def test_an_ing_word_between_a_count_and_people_describes_them(world, sentence, label, count):
    groups = read_prompt(sentence, load_world(world)).groups
    assert [(g.label, g.count.value) for g in groups] == [(label, count)]


@pytest.mark.parametrize("world, sentence, label, count", TAKEN)
def test_people_described_by_an_ing_word_are_taken_along(world, sentence, label, count):
    groups = read_prompt(sentence, load_world(world)).groups
    assert any(g.label == label and g.count.value == count and g.intent == "follow" for g in groups)


@pytest.mark.parametrize("world, sentence", EVENTS)
def test_an_event_people_come_for_is_no_unknown_place(world, sentence):
    assert read_prompt(sentence, load_world(world)).unknown_places == ()


def test_heading_for_an_event_the_world_lacks_is_still_refused():
    assert read_prompt("Two guests head for the wedding.", load_world("mall")).unknown_places == ("wedding",)
