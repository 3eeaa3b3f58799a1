"""Round 46 (r46a): a body part a thing is held in ("clipboard in hand", "a toddler on her hip") and a
time said by an event or a break ("at the interval", "mid-lecture", "halfway through the concert") say no
place: nothing is refused (language/held_and_spans.py). A room named so is still a place."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("aquarium", "Bucket in hand, a keeper walks from the life support room to the exit."),
    ("botanic_garden", "A gardener, secateurs in hand, wanders to the exit."),
    ("dental_clinic", "A mum with a toddler on her hip walks to the exit."),
    ("city_farm", "A farmer with a lamb under one arm walks to the exit."),
])
def test_a_thing_held_in_hand_is_no_place(read, world, prompt):
    reading = read(world, prompt)
    assert reading.unknown_places == ()
    assert reading.groups[-1].intent == "walk"


@pytest.mark.parametrize("world,prompt", [
    ("aquarium", "At the interval the fire alarm sounds and everyone in the cafe leaves."),
    ("hospital", "At half-time two porters walk to the pharmacy."),
    ("bowling_alley", "Mid-match the smoke detectors go off and everyone leaves."),
    ("playhouse", "Halfway through the concert, two ushers walk to the exit."),
    ("maternity_unit", "Mid-seminar the fire alarm goes off and the midwives leave."),
])
def test_a_time_said_by_an_event_is_no_place(read, world, prompt):
    assert read(world, prompt).unknown_places == ()


def test_a_room_named_by_a_break_is_still_refused_when_missing(read):
    assert read("aquarium", "Two keepers wait at the break room.").unknown_places == ("break room",)
