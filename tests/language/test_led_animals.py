"""An animal led, walked or carried along is no person, by kind, not by a list (led_animals.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,label", [
    ("city_farm", "A farmer leads two heifers into the big barn.", "farmer"),
    ("riding_stables", "A groom leads a skittish mare from the front stables to the lunge pen.", "groom"),
])
def test_a_led_animal_is_no_group(read, world, prompt, label):
    assert [g.label for g in read(world, prompt).groups] == [label]


def test_a_led_person_is_still_a_group(read):
    groups = read("city_farm", "A nurse leads a patient into the big barn.").groups
    assert [g.label for g in groups] == ["nurse", "patient"]


def test_a_guided_first_timer_is_a_person(read):
    groups = read("city_farm", "A keeper guides a nervous first-timer from the farm shop to the farmyard.").groups
    assert [g.intent for g in groups] == ["walk", "follow"]
