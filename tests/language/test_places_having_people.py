"""People said as what a place or a team has (language/places_having_people.py): "the boardroom has nine
managers in session", "the sales team has six reps in the boardroom" are that many people there; a bare
activity after them ("in induction", "on a break") is no place; a person who has people is left alone."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,value,location", [
    ("office", "The boardroom has nine managers in session.", 9, "boardroom"),
    ("office", "Meanwhile the kitchen has two interns on a break, and a cleaner mops the corridor.", 2, "kitchen"),
    ("office", "The sales team has six reps in the boardroom.", 6, "boardroom"),
    ("hospital", "The hospital has a dozen patients in the waiting room.", 12, "main_waiting_room"),
    ("hospital", "The pharmacy has three customers in the queue.", 3, "pharmacy"),
    ("museum", "A guard dozes by the entrance and the cafe has five pensioners in conversation.", 5, "cafe"),
])
def test_a_place_or_team_that_has_n_people_is_a_group_of_n_there(read, world, prompt, value, location):
    reading = read(world, prompt)
    group = next(g for g in reading.groups if g.count.value == value)
    assert group.count.kind == "exact" and group.location == location
    assert reading.unknown_places == ()


@pytest.mark.parametrize("world,prompt", [
    ("office", "The receptionist has two visitors at the front desk."),
    ("hospital", "The nurse has three patients in ward B."),
])
def test_a_person_who_has_people_is_left_alone(read, world, prompt):
    groups = read(world, prompt).groups
    assert any(g.count.value == 1 for g in groups)
