"""Probe round r64c: people counted in a "where" clause right after the robot's place, with no comma
("the robot brings coffee to the boardroom where eight people are in a meeting"), are a group at that
place (language/where_commas.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count,place", [
    ("hospital", "The robot takes the trolley to the cafeteria where about twenty staff are having lunch.",
     20, "cafeteria"),
    ("station", "The robot waits by the newsagent where three commuters are buying papers.", 3, "newsagent"),
    ("office", "A robot rolls into the kitchen where five colleagues are making tea.", 5, "kitchen"),
])
def test_counted_people_of_a_where_clause_are_a_group_there(read, world, prompt, count, place):
    (group,) = read(world, prompt).groups
    assert group.count.value == count
    assert place in (group.location, group.destination, group.start)


def test_an_uncounted_where_clause_still_only_says_the_place(read):
    reading = read("hospital", "The robot goes to the room where staff sit.")
    assert not any(g.label == "staff" and g.count.kind == "exact" and g.count.value > 1 for g in reading.groups)
