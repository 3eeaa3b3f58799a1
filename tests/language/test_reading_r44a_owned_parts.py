"""A person and a counted part of their own people ("the consultant and two of her registrars walk ...")
are two groups, of one and of as many as said, both doing the clause; the possessed people add no
vague whole of their own (language/owned_parts.py). And "his office" / "her office" in a clause read for
a group of several is the room of the one person said before them (language/possessive_owners.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,counts,start,destination", [
    ("hospital", "The consultant and two of her registrars walk from the cafeteria to ward B.", [1, 2], "cafeteria",
     "ward_b"),
    ("office", "The manager and two of his interns walk from the kitchen to the boardroom.", [1, 2], "kitchen",
     "boardroom"),
    ("mall", "A mum and two of her kids walk from the food court to the toy shop.", [1, 2], "food_court", "toy_store"),
])
def test_a_person_and_a_part_of_their_own_people_are_two_groups(read, world, prompt, counts, start, destination):
    groups = read(world, prompt).groups
    assert [g.count.value for g in groups] == counts
    assert all((g.intent, g.start, g.destination, g.relation) == ("walk", start, destination, None) for g in groups)


def test_a_part_of_a_counted_whole_keeps_its_whole(read):
    groups = read("hospital", "Two of the six porters walk to ward B.").groups
    assert [g.count.value for g in groups] == [6, 2] and groups[1].relation == "subset_of:0"


@pytest.mark.parametrize("world,prompt,start", [
    ("office", "The manager and two interns walk from his office to the boardroom.", "manager_office"),
    ("primary_school", "The head and four pupils walk from her office to the hall.", "head_office"),
])
def test_his_or_her_room_is_the_single_person_s_for_the_group_with_them(read, world, prompt, start):
    groups = read(world, prompt).groups
    assert [g.start for g in groups] == [start, start]
