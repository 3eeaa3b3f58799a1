"""Round 70 (r70a): an order setting up two groups, the first doing something before its place ("Have
one porter sorting linen in the pharmacy and two nurses in the cafeteria"), or said with "Place",
gives both groups at their places (language/setup_doings.py, language/setup_orders.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,places", [
    ("hospital", "Have one porter sorting linen in the pharmacy and two nurses in the cafeteria.",
     ["pharmacy", "cafeteria"]),
    ("hospital", "Have a doctor reading notes by the pharmacy and three patients in radiology.",
     ["pharmacy", "radiology"]),
    ("hospital", "Place two cleaners in the cafeteria and one visitor by the pharmacy.", ["cafeteria", "pharmacy"]),
])
def test_both_set_up_groups_are_read(read, world, prompt, places):
    groups = read(world, prompt).groups
    assert [g.location for g in groups] == places


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "Put two porters in the cafeteria and one group leader by the pharmacy."),
    ("hospital", "Have three visitors in the cafeteria and a team leader by the pharmacy."),
])
def test_a_leader_named_by_a_collective_is_one_person(read, world, prompt):
    first, leader = read(world, prompt).groups
    assert leader.count.value == 1 and leader.location == "pharmacy"
