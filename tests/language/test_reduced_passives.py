"""People taken somewhere said with a bare participle and "by" (round 71): the taker walks, the taken follow."""

from __future__ import annotations

import pytest

CASES = [
    ("care_home", "A resident pushed by her daughter to the garden.", "garden"),
    ("mall", "Two small kids, pulled by their grandad in a wagon, roll into the food court.", "food_court"),
    ("museum", "Meanwhile an old man wheeled by a volunteer heads for the cafe.", "cafe"),
    ("library", "A pupil with a broken leg, pushed by two classmates, rolls over to the issue desk.", "issue_desk"),
]


@pytest.mark.parametrize(("world", "prompt", "place"), CASES)
def test_the_taken_follow_their_taker(read, world, prompt, place):
    groups = read(world, prompt).groups
    assert len(groups) == 2
    taken, taker = groups
    assert taken.intent == "follow" and taken.follows == taker.who
    assert taker.intent == "walk" and taker.destination == place


def test_a_stay_after_the_participle_is_left_alone(read):
    groups = read("care_home", "A resident pushed by a carer waits in the lounge.").groups
    assert all(g.intent == "wait" for g in groups)


def test_the_taken_as_an_object_is_left_alone(read):
    reading = read("hospital", "The robot passes a patient wheeled by a porter.")
    assert all(g.intent != "follow" for g in reading.groups)


def test_accompanied_people_walk_themselves(read):
    groups = read("library", "A new reader, accompanied by a librarian, walks to the reading room.").groups
    assert groups[0].intent == "walk"
