"""Informal words for children and adults (language/informal_people.py): a counted number of "sprogs",
"bairns", "grown-ups" or "geezers" is that many people, not a vague crowd."""

from __future__ import annotations

import pytest

from grove_tui.language.informal_people import plain_people


@pytest.mark.parametrize("typed,read", [
    ("Five sprogs run", "Five kids run"),
    ("two grown-ups and a rugrat", "two adults and a kid"),
    ("three ankle-biters", "three kids"),
    ("two gents walk to the gents", "two gents walk to the gents"),
])
def test_plain_people(typed, read):
    assert plain_people(typed) == read


@pytest.mark.parametrize("world,prompt,counts", [
    ("zoo", "Five sprogs run from the penguin pool to the cafe.", [5]),
    ("soft_play_centre", "Four bairns scramble into the ball pit.", [4]),
    ("hospital", "Three grown-ups and two rugrats wait in the cafeteria.", [3, 2]),
    ("mall", "Two geezers stroll to the food court.", [2]),
    ("outlet_village", "Curious, seven nippers clamber out of the sandpit and trail along in the robot's wake "
                       "to see what it does.", [7]),
])
def test_counted_informal_people(read, world, prompt, counts):
    reading = read(world, prompt)
    assert [g.count.value for g in reading.groups] == counts
    assert all(g.count.kind == "exact" for g in reading.groups)
