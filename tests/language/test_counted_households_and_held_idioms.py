"""A household or a party said with its size (lexicon.py's collectives: "a household of six", "a
threesome", "a fourball of golfers"), and an idiom of holding or of pace after a comma or a verb ("passports
at the ready", "at the double", language/times_and_manners.py), which is no place to refuse."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,value,start,destination", [
    ("mall", "A household of six drift from the food court to the cinema.", 6, "food_court", "cinema_lobby"),
    ("museum", "A household of three wanders out of the cafe into the entrance hall.", 3, "cafe", "entrance_hall"),
    ("airport", "A party of seven, bags in hand, walk from the cafe to gate B2.", 7, "cafe", "gate_b2"),
])
def test_a_household_or_party_of_n_is_n_people_going_together(read, world, prompt, value, start, destination):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    assert (groups[0].count.kind, groups[0].count.value) == ("exact", value)
    assert (groups[0].intent, groups[0].start, groups[0].destination) == ("walk", start, destination)


@pytest.mark.parametrize("world,prompt,value", [
    ("mall", "A threesome of teenagers stroll to the food court.", 3),
    ("airport", "A fourball of golfers walk from the check-in hall to the cafe.", 4),
    ("hospital", "A fivesome of students wait in the cafeteria.", 5),
    ("station", "A quartet of buskers hang about on platform 1.", 4),
])
def test_a_size_noun_counts_its_members(read, world, prompt, value):
    groups = read(world, prompt).groups
    assert len(groups) == 1 and groups[0].count.value == value


@pytest.mark.parametrize("world,prompt", [
    ("airport", "A family of five, passports at the ready, queue at security."),
    ("station", "Two commuters, tickets at the ready, wait on platform 2."),
    ("office", "A pair of couriers head to reception at the double."),
    ("museum", "A guide hurries to the cafe at a trot."),
])
def test_a_held_or_pace_idiom_is_no_place(read, world, prompt):
    reading = read(world, prompt)
    assert reading.unknown_places == ()
    assert all(g.location or g.destination for g in reading.groups)
