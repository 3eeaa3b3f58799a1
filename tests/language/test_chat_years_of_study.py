"""Round 59 (r59a): students counted by their year of study in chat ("6 second yrs in the library") are
people, and a bare count doing something after "+" or "&" ("+ 3 doing laundry in the laundry") is a
second group (language/chat_years.py, language/chat_people.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,counts", [
    ("university", "6 second yrs in the library + 3 doing crosswords in the café", [6, 3]),
    ("station", "2 cleaners on concourse & 3 doing crossword on the bench", [2, 3]),
    ("hall_of_residence", "3 final yrs in kitchen A + 2 doing laundry in the laundry", [3, 2]),
])
def test_counted_years_of_study_and_a_joined_bare_count(read, world, prompt, counts):
    reading = read(world, prompt)
    assert [g.count.value for g in reading.groups] == counts


def test_the_second_item_keeps_its_place(read):
    reading = read("hall_of_residence", "3 final yrs in kitchen A + 2 doing laundry in the laundry")
    assert reading.groups[1].location == "laundry"
    assert reading.groups[0].label == "student"
