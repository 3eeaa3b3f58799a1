""""the back row of X" is in X (language/place_phrases.py past_part); "her room", "their rooms", "their dorm"
where people have rooms of their own (bedrooms, guest rooms, dorms) is one of those, not a shared lounge
of their kind (language/place_possessed.py own_rooms); a room owned by kind still decides."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, place", [
    ("hospital", "Three patients wait in the back row of the waiting room.", "main_waiting_room"),
    ("cinema", "A couple sit in the back row of screen 2.", "screen_2"),
])
def test_a_row_of_a_room_is_in_the_room(read, world, prompt, place):
    assert read(world, prompt).groups[0].location == place


@pytest.mark.parametrize("world, prompt, rooms", [
    ("care_home", "A resident goes back to her room.", "room_"),
    ("hotel", "A couple head back up to their room.", "room_"),
    ("hospice", "A patient returns to his room.", "bedroom_"),
])
def test_ones_own_room_is_a_room_of_ones_own(read, world, prompt, rooms):
    assert (read(world, prompt).groups[0].destination or "").startswith(rooms)


@pytest.mark.parametrize("world, prompt, place", [
    ("residential", "Mum goes up to her room.", "master_bedroom"),
    ("care_home", "The manager goes back to her office.", "manager_office"),
    ("care_home", "Residents doze in their lounge.", "lounge"),
])
def test_an_owned_room_by_kind_still_decides(read, world, prompt, place):
    g = read(world, prompt).groups[0]
    assert place in (g.destination, g.location)


@pytest.mark.parametrize("world, prompt, place", [
    ("youth_hostel", "Three backpackers head back to their dorm.", "dorm_"),
    ("hall_of_residence", "A student goes back to her room.", "bedroom_"),
])
def test_ones_own_room_by_its_kind(read, world, prompt, place):
    assert (read(world, prompt).groups[0].destination or "").startswith(place)
