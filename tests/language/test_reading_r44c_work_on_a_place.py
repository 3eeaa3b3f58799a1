"""Work done on a place: a verb written with a hyphened prefix ("re-cable", "re-stocks", "re-price") is one
verb, so its people are counted and its object is where they work; and a noun the parser makes the
object ("swap a failed drive in row B") is no verb of going, so the place after it is where they work,
not where they start. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, count, location", [
    ("data_centre", "Have two contractors re-cable the top of row B.", 2, "rack_row_b"),
    ("data_centre", "An engineer re-seats the cables in the meet-me room.", 1, "meet_me_room"),
    ("supermarket", "A shelf stacker re-stocks the bakery shelves.", 1, "bakery"),
    ("supermarket", "Two staff re-price the freezers.", 2, "frozen_foods"),
])
def test_a_prefixed_verb_works_on_its_place(read, world, prompt, count, location):
    group = read(world, prompt).groups[0]
    assert (group.count.value, group.location) == (count, location)


@pytest.mark.parametrize("world, prompt, location", [
    ("data_centre", "While a pair of engineers swap a failed drive in row B, the robot waits in the corridor.", "rack_row_b"),
    ("data_centre", "A pair of engineers swap a failed drive in row B.", "rack_row_b"),
    ("karting_centre", "Two mechanics fix a broken kart in the workshop.", "workshop"),
])
def test_a_noun_object_is_no_verb_of_going(read, world, prompt, location):
    group = read(world, prompt).groups[0]
    assert group.intent == "wait"
    assert group.location == location
