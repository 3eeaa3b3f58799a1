"""Round 44 (r44b): people said inside a "where" clause after a preposition ("runs to where staff look
after children who got separated from their parents"): the clause only says which place; its people,
subject or object, are no group of the scene (language/where_people.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count", [
    ("mall", "A worried dad hurries from the food court to where the guards keep lost children.", 1),
    ("hospital", "Two porters walk from the lobby to where the nurses look after the newborn babies.", 2),
    ("zoo", "A keeper strolls over to where the volunteers feed the goats.", 1),
])
def test_people_in_a_place_said_by_a_where_clause_are_no_group(read, world, prompt, count):
    (group,) = read(world, prompt).groups
    assert group.count.value == count


def test_a_group_after_the_where_clause_is_still_read(read):
    reading = read("mall", "A dad hurries to where the guards keep lost children, and two cleaners mop the food court.")
    assert [g.count.value for g in reading.groups] == [1, 2]
