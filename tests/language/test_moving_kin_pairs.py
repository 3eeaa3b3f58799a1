"""A person and their parent going somewhere together (language/moving_kin_pairs.py) are one group of two
walking; a person still to become one ("a groom-to-be", "brides-to-be") or a relative by marriage is a person
(hyphened_people.py). People joined by "and" who stay or talk keep a group each."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,destination", [
    ("hospital", "A groom-to-be and his father head up to ward B.", "ward_b"),
    ("mall", "A bride-to-be and her mum wander over to the food court.", "food_court"),
    ("museum", "A young lad and his dad slowly make their way to the cafe.", "cafe"),
    ("station", "A mum-to-be and her husband walk to platform 2.", "platform_2"),
])
def test_a_person_and_their_parent_going_somewhere_are_one_pair(read, world, prompt, destination):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    assert groups[0].count.value == 2 and groups[0].intent == "walk" and groups[0].destination == destination


@pytest.mark.parametrize("world,prompt,value", [
    ("hospital", "Two brides-to-be wait in the cafeteria.", 2),
    ("residential", "My mother-in-law naps on the sofa.", 1),
    ("office", "A dad-to-be paces in the corridor.", 1),
])
def test_a_hyphened_person_word_is_a_person(read, world, prompt, value):
    groups = read(world, prompt).groups
    assert len(groups) == 1 and groups[0].count.value == value
    assert groups[0].location is not None


def test_people_and_a_parent_who_talk_stay_two_groups(read):
    groups = read("hospital", "A nurse and her mother chat in the cafeteria.").groups
    assert len(groups) == 2
