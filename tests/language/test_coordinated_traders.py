"""A trade's word the world also gives a room, joined by "and" to another person, the two the subject of
one verb (round 71): each is a person ("the butcher and a customer chat ..."), not a room and one person."""

from __future__ import annotations

import pytest

CASES = [
    ("market_hall", "The butcher and a customer wait by the flower stall."),
    ("ferry_terminal", "A cleaner and the newsagent head to the cafe."),
    ("mall", "The chemist and two shoppers walk to the food court."),
]


@pytest.mark.parametrize(("world", "prompt"), CASES)
def test_both_are_people(read, world, prompt):
    groups = read(world, prompt).groups
    assert len(groups) == 2
    assert all(g.intent in ("wait", "walk") for g in groups)


def test_the_room_after_a_verb_stays_a_room(read):
    groups = read("mall", "Two shoppers wait at the chemist.").groups
    assert [g.count.value for g in groups] == [2]
