"""A family said by its surname in the plural is one family (language/plural_surnames.py): as many as "a family"
when nothing says how many, each surname its own family, and a count set off by commas still says how many."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

ONE_FAMILY = [
    ("residential", "The Nguyens wait in the hallway.", "wait", "hallway"),
    ("museum", "the Kowalskis stroll over to the gift shop", "walk", "gift_shop"),
    ("mall", "After lunch the Okonjos head to the bookshop.", "walk", "bookshop"),
]
TWO_FAMILIES = [
    ("mall", "The Ferreiras browse in the bookshop while the Haddads sit by the fountain."),
    ("residential", "the Lindqvists and the Moreaus chat in the kitchen"),
]
NOT_FAMILIES = [
    ("mall", "The shoppers wander to the bookshop."),  # a capital only at the start
    ("residential", "Mr and Mrs Smith walk to the kitchen."),
]


@pytest.mark.parametrize("world, sentence, intent, place", ONE_FAMILY)
def test_a_plural_surname_is_one_family_as_big_as_a_family(world, sentence, intent, place):
    groups = read_prompt(sentence, load_world(world)).groups
    assert len(groups) == 1
    group = groups[0]
    assert (group.label, group.intent, group.count.kind, group.count.low, group.count.high) == \
        ("family", intent, "implied", 3, 4)
    assert place in (group.destination, group.location)


@pytest.mark.parametrize("world, sentence", TWO_FAMILIES)
def test_two_surnames_are_two_families(world, sentence):
    groups = read_prompt(sentence, load_world(world)).groups
    assert [g.label for g in groups] == ["family", "family"]


def test_a_count_in_commas_still_says_how_many_the_family_is():
    group = read_prompt("The Abernathys, all six of them, leave the kitchen.", load_world("residential")).groups[0]
    assert (group.count.value, group.start) == (6, "kitchen")


@pytest.mark.parametrize("world, sentence", NOT_FAMILIES)
def test_capitals_without_a_surname_make_no_family(world, sentence):
    assert all(g.label != "family" for g in read_prompt(sentence, load_world(world)).groups)
