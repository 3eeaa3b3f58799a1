"""Clause and place classes of round 15, each with sentences of its own over at least two worlds (none
from the understanding sets): idle verbs ("hang out", "loiter", "lounge about") are waiting unless talk
is said; a possessive room name ("the manager's office") is the owner's room, before a thing inside it
that shares the head; "round to X" is going to X, not wandering; "wander round the X" in a world with
"round tables" is no place "round"."""

from __future__ import annotations

import pytest

# ---- A. idle verbs: waiting where they are, converse only when talk is said ---------------------------


@pytest.mark.parametrize("world,prompt,intent,location", [
    ("mall", "Three lads hang out by the fountain", "wait", "fountain"),
    ("cinema", "Five teenagers hang out by the popcorn stand", "wait", "concessions_counter"),
    ("convention_centre", "Four delegates hang out by the registration desk", "wait", "registration_desk"),
    ("convention_centre", "An exhibitor strolls down to the catering area and hangs out there", "wait",
     "catering_area"),
])
def test_hanging_out_is_waiting_unless_talk_is_said(read, world, prompt, intent, location):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.location) == (intent, location)


# ---- B. a possessive room name is the owner's room, not a thing in it ---------------------------------


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("cinema", "An usher heads out of the staff room to the manager's office", "staff_room", "manager_office"),
    ("cinema", "The projectionist comes out of his booth and goes to the manager's office", "projection_room",
     "manager_office"),
    ("cinema", "An usher goes up to the duty manager's office", None, "manager_office"),
])
def test_a_possessive_room_name_is_the_room(read, world, prompt, start, destination):
    reading = read(world, prompt)
    group = reading.groups[0]
    assert (group.intent, group.start, group.destination) == ("walk", start, destination)
    assert reading.unknown_places == ()


# ---- C. "round to X" goes to X; "round" is never a place ---------------------------------------------


@pytest.mark.parametrize("world,prompt,destination", [
    ("cinema", "An usher walks round to the bar", "bar"),
    ("cinema", "A cleaner wanders round to the toilets", "toilets"),
    ("hospital", "A porter walks round to the pharmacy", "pharmacy"),
    ("hotel", "A maid wanders round to the laundry", "laundry"),
    ("convention_centre", "A steward strolls around to the cloakroom", "cloakroom"),
])
def test_round_to_a_place_is_a_walk_there(read, world, prompt, destination):
    reading = read(world, prompt)
    group = reading.groups[0]
    assert (group.intent, group.destination) == ("walk", destination)
    assert reading.unknown_places == ()


@pytest.mark.parametrize("world,prompt,location", [
    ("hotel", "Two guests wander round the bar", "bar"),
    ("hotel", "A porter wanders round the lobby", "lobby"),
])
def test_wandering_round_a_room_names_no_place_round(read, world, prompt, location):
    reading = read(world, prompt)
    group = reading.groups[0]
    assert (group.intent, group.location) == ("wander", location)
    assert reading.unknown_places == ()
