"""Round 44: wandering needs room to wander in. Said of a thing by a word of nearness ("mill about near
the ticket machines"), the people stay at that spot and wait; said of a room or an area they wander."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,where", [
    ("mall", "Two lads drift about beside the fountain.", "fountain"),
    ("station", "A handful of commuters mill around near the departures board.", "departure_board"),
    ("hospital", "A couple of visitors hang around by the coffee machine.", "coffee_machine"),
])
def test_wandering_by_a_thing_is_waiting_there(read, world, prompt, where):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.location) == ("wait", where)


@pytest.mark.parametrize("world,prompt,where", [
    ("station", "Five commuters mill around the concourse.", "concourse"),
    ("mall", "Two lads wander around the atrium.", "main_atrium"),
    ("airport", "A dozen travellers browse the perfume shelves in the duty free.", None),
])
def test_wandering_an_area_is_still_wandering(read, world, prompt, where):
    (g,) = read(world, prompt).groups
    assert g.intent == "wander"
    assert where is None or g.location == where


@pytest.mark.parametrize("world,prompt", [
    ("mall", "A guard patrols near the fountain."),
    ("station", "A cleaner sweeps by the ticket machines."),
])
def test_a_round_or_a_chore_by_a_thing_still_goes_about(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.intent == "wander"
