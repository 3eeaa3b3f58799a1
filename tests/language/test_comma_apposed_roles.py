"""A role and a name said one between commas (round 71): "the steward, Kemi, shows ...", "our driver,
Mr Ansah, takes ...": one person, whose verb keeps the people it takes along."""

from __future__ import annotations

import pytest

CASES = [
    ("station", "The steward, Kemi, shows three passengers to platform 2.", 3),
    ("airport", "Our driver, Mr Ansah, takes a family of four to the check-in desks.", 4),
    ("library", "A volunteer, Jo Bell, guides five pensioners to the reading room.", 5),
]


@pytest.mark.parametrize(("world", "prompt", "taken"), CASES)
def test_the_taken_are_kept(read, world, prompt, taken):
    groups = read(world, prompt).groups
    assert len(groups) == 2
    leader, led = groups
    assert leader.count.value == 1 and leader.intent == "walk"
    assert led.count.value == taken and led.intent == "follow"


def test_a_list_of_names_is_no_apposition(read):
    groups = read("hospital", "Ama, Kofi and their gran wait in the cafe.").groups
    assert sum(g.count.value or 0 for g in groups) == 3


def test_a_role_with_modifiers_before_the_name(read):
    groups = read("airport", "The Year 10 coach driver, Mr Pike, takes four pupils to gate B1.").groups
    assert [g.count.value for g in groups] == [1, 4]
    assert groups[1].intent == "follow"
