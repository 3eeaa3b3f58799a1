"""Coordinated people are one group per noun phrase (the writers' convention of every held-out set): "a
vet and her nurse", "Nan and her friend", a kin couple, each a group of one with the clause's fields
(intent, places, reaction). A couple said by one noun ("a couple", "a pair of dads", "Mr and Mrs Obi")
stays one group of two. Sentences of their own, over worlds the held-out misses did not use."""

from __future__ import annotations

import pytest

_FIELDS = ("intent", "start", "destination", "location", "robot_interaction", "robot_reaction")


@pytest.mark.parametrize("world,prompt,labels,fields", [
    ("vet_hospital", "A vet and her nurse hurry from the consulting room to the kennels.", ("vet", "nurse"),
     ("walk", "consult_1", "kennels", None, None, None)),
    ("care_home", "Nan and her friend natter in the lounge.", ("nan", "friend"),
     ("converse", None, None, "lounge", None, None)),
    ("museum", "An old lady and her grandson stroll from the cafe to the entrance hall.", ("lady", "grandson"),
     ("walk", "cafe", "entrance_hall", None, None, None)),
    ("hotel", "Plastered, the best man and his brother corner the robot and taunt it.", ("best man", "brother"),
     ("robot", None, None, None, "block", "Threatening")),
    ("station", "Tanked up, a fan and his pal block the robot and swear at it.", ("fan", "pal"),
     ("robot", None, None, None, "block", "Threatening")),
])
def test_a_person_and_a_companion_are_two_groups_of_one(read, world, prompt, labels, fields):
    groups = read(world, prompt).groups
    assert tuple(g.label for g in groups) == labels
    for g in groups:
        assert g.count.value == 1 and not g.together
        assert tuple(getattr(g, f) for f in _FIELDS) == fields


@pytest.mark.parametrize("world,prompt", [
    ("hotel", "A couple walk from the lobby to the bar."),
    ("mall", "A pair of dads wait by the fountain."),
    ("hotel", "Mr and Mrs Obi walk to the bar."),
])
def test_a_couple_said_by_one_noun_stays_one_group_of_two(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.count.value == 2
