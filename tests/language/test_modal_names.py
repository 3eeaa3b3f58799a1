"""A first name that is also a modal ("Will") is one person (language/modal_names.py): "Will waits in
the lounge", "Grace and Will walk", "Will queues at the desk"; "will walk" stays a modal."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

ALONE = [
    ("residential", "Will naps in the living room.", "living_room"),
    ("station", "Will queues at the ticket office.", "ticket_office"),
    ("museum", "Will strolls from the cafe to the dinosaur gallery.", "dinosaur_gallery"),
]


@pytest.mark.parametrize("world, sentence, place", ALONE)
def test_will_opening_a_sentence_is_one_person(world, sentence, place):
    group, = read_prompt(sentence, load_world(world)).groups
    assert (group.label, group.count.kind, group.count.value) == ("will", "exact", 1)
    assert place in (group.location, group.destination)


@pytest.mark.parametrize("world, sentence, names", [
    ("airport", "Priya and Will walk from the check-in hall to security.", ["priya", "will"]),
])
def test_will_in_a_list_of_names_is_one_person(world, sentence, names):
    groups = read_prompt(sentence, load_world(world)).groups
    assert [g.label for g in groups] == names
    assert all(g.count.value == 1 for g in groups)


def test_will_in_a_list_of_three_names_is_one_of_the_group():
    (group,) = read_prompt("Tom, Anna and Will chat in the kitchen.", load_world("office")).groups
    assert group.count.value == 3  # a list of names is one group of that many (language/named_lists.py)


def test_will_as_a_modal_names_nobody():
    group, = read_prompt("Five visitors will wait in the cafe.", load_world("museum")).groups
    assert (group.label, group.count.value) == ("visitor", 5)
