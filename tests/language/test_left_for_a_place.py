"""Leaving one place for another (issue 29): "leave / quit X for Y" is a walk from X to Y, and a phrase after "and" behind Y that names no place is what they go there for."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start,destination,purpose", [
    ("hospital", "Two porters quit the cafeteria for the pharmacy and a chat.", "cafeteria", "pharmacy", "chat"),
    ("hospital", "Three orderlies quit the cafeteria for the pharmacy and a late lunch.", "cafeteria", "pharmacy",
     "lunch"),
    ("office", "Three cleaners leave the kitchen for the boardroom and the weekly meeting.", "kitchen", "boardroom",
     "meeting"),
])
def test_leaving_a_place_for_another(read, world, prompt, start, destination, purpose):
    reading = read(world, prompt)
    assert len(reading.groups) == 1 and reading.unknown_places == ()
    g = reading.groups[0]
    assert (g.intent, g.start, g.destination) == ("walk", start, destination)
    assert (g.purpose is None) if purpose is None else (purpose in (g.purpose or ""))


def test_a_person_after_and_is_no_purpose(read):
    reading = read("office", "Three cleaners leave the kitchen for the boardroom and the staff wait.")
    assert reading.groups[0].purpose is None and reading.groups[0].destination == "boardroom"
