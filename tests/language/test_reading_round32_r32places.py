"""Place classes of round 32, each with sentences of its own over at least two worlds (none from the
understanding sets): a door named by whose it is (a room, or a thing in the room) is that room's own door, not the room or the thing."""

from __future__ import annotations

import pytest


# ---- 2. a door named by whose it is: that room's own door -------------------------------------------------

@pytest.mark.parametrize("world,prompt,door", [
    ("art_gallery", "Thirty visitors leave through the Hokusai show's emergency door.", "temporary_fire_exit"),
    ("art_gallery", "A dozen visitors hurry out through the great wave's fire door.", "temporary_fire_exit"),
    ("cinema", "The audience of the late film leave through the bar's emergency door.", "bar_street_door"),
    ("cinema", "Fifty moviegoers are led out through the cocktail bar's fire door.", "bar_street_door"),
    ("mall", "Forty shoppers leave through the supermarket checkout's emergency door.", "supermarket_exit"),
])
def test_a_door_named_by_whose_it_is_is_that_rooms_door(read, world, prompt, door):
    (g,) = read(world, prompt).groups
    assert g.destination == door
    assert g.via == ()


@pytest.mark.parametrize("world,prompt,door", [
    ("hospital", "Ten visitors leave through the canteen's door.", "cafeteria_door"),
    ("art_gallery", "Twenty visitors leave through the café's terrace door.", "cafe_terrace_door"),
    ("art_gallery", "Thirty visitors leave through the temporary exhibition's fire exit.", "temporary_fire_exit"),
    ("museum", "Forty visitors leave through the dinosaur gallery's emergency exit.", "fire_exit"),
])
def test_doors_of_rooms_read_already_keep_their_reading(read, world, prompt, door):
    assert read(world, prompt).groups[0].destination == door


# ---- 3. a room said by what is done there: to people (a passive), or imaging in everyday words ----------

@pytest.mark.parametrize("world,prompt,destination", [
    ("tv_studio", "Both contestants walk from the canteen to the place where guests get powdered.", "make_up"),
    ("tv_studio", "A presenter walks from the canteen to the room where presenters get powdered.", "make_up"),
    ("tv_studio", "A presenter hurries from the canteen to where you get powdered.", "make_up"),
    ("dental_clinic", "A boy walks from the waiting room to the room where they take photos of your teeth.", "xray_room"),
    ("dental_clinic", "A patient walks from reception to where they photograph your jaw.", "xray_room"),
    ("hospital", "Two nurses walk from the cafeteria to the place where they take pictures of your chest.", "radiology"),
    ("vet_hospital", "A vet walks from the waiting room to where they take photos of a dog's insides.", "prep_room"),
])
def test_a_room_said_by_what_is_done_there_is_that_room(read, world, prompt, destination):
    assert read(world, prompt).groups[0].destination == destination


@pytest.mark.parametrize("world,prompt,destination", [
    ("tv_studio", "A singer walks from the canteen to where the stars get their faces done.", "make_up"),
    ("dental_clinic", "A patient walks from reception to where they x-ray your teeth.", "xray_room"),
    ("hospital", "A porter walks from the lobby to the department where they take x-rays.", "radiology"),
    ("office", "Two visitors walk from reception to where you get a coffee.", "coffee_machine"),
])
def test_rooms_said_by_what_is_done_there_read_already_keep_their_reading(read, world, prompt, destination):
    assert read(world, prompt).groups[0].destination == destination
