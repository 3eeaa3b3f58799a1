"""A role, then the person's name, then their verb is one person (language/apposed_names.py):
"my colleague Sam walks", "our driver Tom waits"."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

CASES = [
    ("hospital", "My colleague Sam walks to the pharmacy.", "walk"),
    ("hospital", "Our driver Tom waits in the cafeteria.", "wait"),
    ("office", "My manager Alan paces from the kitchen to the boardroom.", "walk"),
    ("museum", "Our guide Priya strolls from the cafe to the dinosaur gallery.", "walk"),
]


@pytest.mark.parametrize("world, sentence, intent", CASES)
def test_a_role_then_a_name_is_one_person(world, sentence, intent):
    group, = read_prompt(sentence, load_world(world)).groups
    assert (group.count.kind, group.count.value, group.intent) == ("exact", 1, intent)


def test_the_named_role_and_another_group_are_two_groups():
    reading = read_prompt("The receptionist Maria walks to the cafeteria while two porters wait at the pharmacy.",
                          load_world("hospital"))
    assert [g.count.value for g in reading.groups] == [1, 2]
