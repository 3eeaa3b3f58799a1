"""Round 44 (r44b): people said by an age band ("eighteen over-fifties", "a dozen under-fives", "two
over-60s", "a few twenty-somethings"): so many people, one group, and a part of them "of them" its subset;
a band naming a club or team ("the over-60s club", "a coach of the under-12s") is left as it is
(language/age_bands.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,kind,value,place", [
    ("gp_surgery", "A dozen under-fives play in the waiting room.", "exact", 12, "waiting_area"),
    ("museum", "Two over-60s shuffle from the foyer to the cafe.", "exact", 2, None),
    ("hotel", "A few twenty-somethings lounge in the lobby.", "vague", None, "lobby"),
])
def test_an_age_band_is_people(read, world, prompt, kind, value, place):
    (group,) = read(world, prompt).groups
    assert group.count.kind == kind and (value is None or group.count.value == value)
    assert place is None or group.location == place


def test_a_part_of_an_age_band_is_its_subset(read):
    whole, part = read("hospital", "Twenty over-seventies wait in the lobby, and five of them walk to the pharmacy.").groups
    assert (whole.count.value, part.count.value, part.relation, part.destination) == (20, 5, "subset_of:0", "pharmacy")


@pytest.mark.parametrize("world,prompt,count", [
    ("museum", "A coach of the under-12s walks to the cafe.", 1),
])
def test_a_band_naming_what_they_belong_to_is_left_alone(read, world, prompt, count):
    (group,) = read(world, prompt).groups
    assert group.count.value == count
