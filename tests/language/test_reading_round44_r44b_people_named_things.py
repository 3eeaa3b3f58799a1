"""Round 44 (r44b): a thing named after the people it is for, by a hyphenated modifier of person words
("before the parent-and-baby session", "the adults-only sauna", "until the kids-only session ends"): the
person words are nobody there, no group (language/people_named_things.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count", [
    ("swimming_baths", "Two lifeguards walk to the pool before the parent-and-child swim.", 2),
    ("swimming_baths", "Six dads wait in the cafe until the kids-only session ends.", 6),
    ("day_spa", "Three friends walk from reception to the adults-only sauna.", 3),
    ("community_centre", "A dozen mums queue in the foyer for the mum-and-toddler session.", 12),
])
def test_person_words_naming_what_a_thing_is_for_are_no_group(read, world, prompt, count):
    (group,) = read(world, prompt).groups
    assert group.count.value == count


def test_the_thing_so_named_is_still_a_place(read):
    (group,) = read("day_spa", "A couple walk from reception to the adults-only sauna.").groups
    assert (group.count.value, group.destination) == (2, "sauna")


def test_an_event_collective_after_a_word_of_time_is_the_event(read):
    (group,) = read("maternity_unit", "Two midwives wait in the lobby before the parent-and-baby class.").groups
    assert group.count.value == 2


def test_a_place_the_world_names_so_keeps_its_name(read):
    (group,) = read("maternity_unit", "Two midwives walk to the mother-and-baby ward.").groups
    assert group.destination == "postnatal_ward"
