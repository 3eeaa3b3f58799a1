"""Places a sentence rules out ("..., not the main doors", "avoiding the lifts") are read as places the
group keeps out of, never as where it goes; a "not" before anything but a place rules nothing out."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt


@pytest.mark.parametrize("world, prompt, avoid, destination", [
    ("residential", "The family in the kitchen get out, not by the back door.", ("back_door",), None),
    ("residential", "Two kids run to the front door rather than the back door.", ("back_door",), "front_door"),
    ("hospital", "Three porters walk from radiology to the cafeteria, avoiding the main waiting room.",
     ("main_waiting_room",), "cafeteria"),
    ("station", "Twenty commuters leave the concourse, but not through the main entrance.", ("main_entrance",), None),
    ("museum", "A school group walks to the auditorium, never through the gift shop.", ("gift_shop",), "auditorium"),
])
def test_a_place_ruled_out_is_kept_out_of_not_gone_to(worlds, world, prompt, avoid, destination):
    reading = read_prompt(prompt, worlds[world])
    assert reading.unknown_places == ()
    group = reading.groups[0]
    assert group.avoid == avoid
    assert group.destination == destination
    assert not set(avoid) & {group.start, group.destination, group.location, *group.via}


def test_a_place_ruled_out_in_a_world_nobody_tuned_on(library):
    reading = read_prompt("Everyone in the reading room leaves by the nearest exit, not the main doors.", library)
    assert reading.groups[0].avoid == ("main_entrance",) and reading.groups[0].start == "reading_room"


@pytest.mark.parametrize("world, prompt", [
    ("hospital", "Two nurses who are not busy wait in the lobby."),
    ("office", "A visitor does not wait long at reception and walks to the kitchen."),
    ("station", "Not many commuters are on platform 1; five walk to the ticket hall."),
])
def test_a_not_before_anything_but_a_place_rules_nothing_out(worlds, world, prompt):
    reading = read_prompt(prompt, worlds[world])
    assert all(g.avoid == () for g in reading.groups)


def test_what_is_ruled_out_round_trips_through_plain_data(worlds):
    from grove_tui.language.model import PromptReading

    reading = read_prompt("The family in the kitchen get out, not by the back door.", worlds["residential"])
    assert PromptReading.from_dict(reading.to_dict()) == reading
