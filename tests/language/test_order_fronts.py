"""A word of order opening a sentence with no comma ("First a man shops in X", "Initially a woman
browses ...") is no part of the subject: the person and their verb are read as without it (order_fronts)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world


@pytest.mark.parametrize("world, sentence, label, count", [
    ("worlds/mall.yaml", "Initially a woman shops in the bookshop.", "woman", 1),
    ("worlds/mall.yaml", "Firstly a couple shops in the supermarket, then they walk to the food court.", "couple", 2),
    ("worlds/airport.yaml", "First a family checks in at the check-in hall, then they walk to gate a1.", "family", 4),
    ("worlds/museum.yaml", "First a guard checks the cloakroom, then he goes to the great hall.", "guard", 1),
])
def test_an_order_word_opening_the_sentence_leaves_the_person_and_verb(world, sentence, label, count):
    groups = read_prompt(sentence, load_world(world)).groups
    assert len(groups) == 1
    assert (groups[0].label, groups[0].count.value) == (label, count)


def test_then_after_a_comma_keeps_the_first_clause_the_persons():
    group = read_prompt("First a couple shops in the supermarket, then they walk to the food court.",
                        load_world("worlds/mall.yaml")).groups[0]
    assert (group.start, group.destination) == ("supermarket", "food_court")
