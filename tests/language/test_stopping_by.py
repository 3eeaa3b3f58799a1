"""A call paid at a place (issue 29): "pops by / calls in at / stops by X to <do>" is going to X; "stops by
X" with no purpose is standing beside it, and "is stopped by security" is no visit. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, goal", [
    ("hospital", "A nurse pops by the pharmacy to pick up some bandages.", "pharmacy"),
    ("office", "A manager calls in at the kitchen to make a coffee.", "kitchen"),
    ("airport", "A pilot stops by the cafe for a quick espresso.", "cafe"),
    ("office", "Two interns swing by the kitchen to grab a snack.", "kitchen"),
])
def test_a_call_paid_at_a_place_is_going_there(read, world, prompt, goal):
    group = read(world, prompt).groups[0]
    assert group.intent == "walk"
    assert group.destination == goal


@pytest.mark.parametrize("world, prompt", [
    ("hospital", "A porter stops by the lifts."),
    ("airport", "A passenger is stopped by security."),
])
def test_stopping_beside_or_being_stopped_is_no_visit(read, world, prompt):
    assert read(world, prompt).groups[0].intent != "walk"
