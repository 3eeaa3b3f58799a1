"""A subject list of three or more single people, roles and relatives among the names, is one group of
that many (language/role_lists.py); a list with a count in it stays a group per item. "2 + nan" in
chat joins two items, it is no "2+" (language/text.py). A hyphenated age with its tens written out is
one person (language/age_nouns.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, size", [
    ("office", "The manager, her deputy and a temp walk together to the meeting room.", 3),
    ("mall", "Priya, her mum and their neighbour wander from the food court to the cinema.", 3),
    ("hospital", "Nurse Hale, Dr Osei and a porter hurry to the emergency department.", 3),
    ("museum", "The curator, a guide, his assistant and a guard cross to the cafe.", 4),
])
def test_a_list_of_single_people_is_one_group(read, world, prompt, size):
    groups = read(world, prompt).groups
    assert len(groups) == 1 and groups[0].count.value == size


def test_a_list_with_a_count_stays_a_group_per_item(read):
    assert len(read("hospital", "A doctor, three nurses and a porter walk to the cafeteria.").groups) == 3


def test_a_chat_plus_after_a_numbered_room_joins_two_items(read):
    groups = read("residential", "sat eve: 2 kids in bedroom 2 + grandad in the kitchen").groups
    assert len(groups) == 2 and groups[0].count.value == 2


@pytest.mark.parametrize("world, prompt, value", [
    ("mall", "A ninety-year-old shuffles from the lifts to the food court.", 1),
    ("station", "Two sixty-five-year-olds wait on platform 1.", 2),
])
def test_an_age_with_its_tens_written_out_is_a_person(read, world, prompt, value):
    g = read(world, prompt).groups[0]
    assert (g.count.kind, g.count.value) == ("exact", value)
