"""One person named by a name, a title or a noun before their verb is one person (language/subject_phrases.py,
unlisted_people.py): the small parser reads the "-s" verb as a plural noun ("Rose potters", "Timmy
bolts"), hangs a name on the verb as a modifier ("Dave scoots", "Tom from sales pops"), or tags a name an
adjective ("Sarah scurries"), and the person was lost to a vague crowd of six."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

ONE = [
    ("office", "Sarah scurries to the kitchen.", "kitchen"),
    ("office", "Dave scoots across from reception to the boardroom.", "boardroom"),
    ("office", "Dave from IT scoots across from reception to the boardroom.", "boardroom"),
    ("office", "Tom from sales pops over from the kitchen to the boardroom.", "boardroom"),
    ("office", "Our intern Bella dawdles by the printer.", None),
    ("station", "Kev legs it from the ticket hall to platform 1.", "platform_1"),
    ("mall", "Grandma Rose potters round the food court.", None),
    ("mall", "Little Timmy bolts from the toy shop to the fountain.", "fountain"),
    ("museum", "Ines sketches by the dinosaur skeleton.", None),
    ("mall", "Santa waves at the kids near the fountain.", None),
    ("airport", "A timid lad beside gate B1 cowers from the robot.", None),
]


@pytest.mark.parametrize("world, sentence, destination", ONE)
def test_one_person_named_before_their_verb_is_one(world, sentence, destination):
    reading = read_prompt(sentence, load_world(world))
    assert len(reading.groups) == 1
    group = reading.groups[0]
    assert (group.count.kind, group.count.value) == ("exact", 1), group.who
    if destination:
        assert group.destination == destination


MANY = [
    ("office", "Small groups of two chat around the coffee corner."),
    ("station", "Nine travellers beside platform 2 wait for the train."),
    ("mall", "Every evening, shoppers from the car park stream into the food court."),
]


@pytest.mark.parametrize("world, sentence", MANY)
def test_people_in_the_plural_stay_many(world, sentence):
    group = read_prompt(sentence, load_world(world)).groups[0]
    assert group.count.value != 1
