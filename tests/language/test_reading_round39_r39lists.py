"""People classes of round 39 (r39lists), each with sentences of its own over at least two worlds (none from the
understanding sets): a relative by marriage ("my sister-in-law", "two brothers-in-law") is one person each, kept
with the clause it is in; a school year's pupils ("thirty Year 5s", "the Year-10s") are that many pupils."""

from __future__ import annotations

import pytest


# ---- 1. relatives by marriage ----------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,count,location", [
    ("residential", "My sister-in-law reads in the kitchen.", 1, "kitchen"),
    ("residential", "Her mother-in-law dozes on the settee while the robot tidies the hall.", 1, "sofa"),
    ("hospital", "My father-in-law waits in the cafeteria.", 1, "cafeteria"),
    ("hotel", "Two brothers-in-law chat in the restaurant.", 2, "restaurant"),
    ("food_court", "My son-in-law sits on the sofas.", 1, "sofas"),
])
def test_a_relative_by_marriage_is_one_person_where_said(read, world, prompt, count, location):
    (g,) = read(world, prompt).groups
    assert g.count.value == count
    assert g.location == location


def test_a_relative_by_marriage_keeps_the_second_clause(read):
    r = read("residential", "My daughter-in-law reads in the kitchen whilst her lad naps on the settee.")
    assert [(g.count.value, g.location) for g in r.groups] == [(1, "kitchen"), (1, "sofa")]


# ---- 2. a school year's pupils --------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,count", [
    ("museum", "Twenty Year 10s sketch in the gallery.", 20),
    ("museum", "Thirty Year 5s sketch in the ancient Egypt gallery, a lone attendant stands by the fire door.", 30),
    ("aquarium", "Fifteen year-6s gather by the shark tunnel.", 15),
    ("primary_school", "A dozen Year 2s line up outside the hall.", 12),
])
def test_a_school_years_pupils_are_that_many_people(read, world, prompt, count):
    r = read(world, prompt)
    assert r.groups[0].count.value == count
    assert r.groups[0].count.kind == "exact"
    assert not r.notes or "no people are named" not in " ".join(r.notes)


# ---- guards -------------------------------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,count", [
    ("museum", "Twenty Year 9 pupils sketch in the gallery.", 20),
    ("residential", "My sister reads in the kitchen.", 1),
    ("museum", "Twenty sixth-formers sketch in the gallery.", 20),
])
def test_people_already_read_keep_their_reading(read, world, prompt, count):
    (g,) = read(world, prompt).groups
    assert g.count.value == count
