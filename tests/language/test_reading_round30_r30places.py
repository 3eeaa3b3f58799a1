"""Round 30 of the reader's places: a hyphenated name is one name ("make-up", "check-in", "goods-in",
"walk-in"): its particle is no preposition that starts another place phrase, and a name whose verb the
reader otherwise drops ("make-up") keeps it, so "the make-up room" is not just "the room"."""

import pytest


# ---- 1. a hyphenated name: its particle is no preposition; "make-up" is a word of the name ---------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("tv_studio", "A runner walks from the green room to the make-up room.", "green_room", "make_up"),
    ("tv_studio", "Two guests leave make-up for the green room.", "make_up", "green_room"),
    ("airport", "Three travellers leave the check-in area for the toilets.", "check_in_hall", "toilets"),
    ("hospital", "A porter leaves the check-in kiosk for the pharmacy.", "checkin_kiosk", "pharmacy"),
    ("gp_surgery", "A dad leaves the check-in screen for the waiting area.", "check_in_screen", "waiting_area"),
    ("market_hall", "A trader leaves the walk-in fridge for the loading bay.", "cold_store", "loading_bay"),
    ("ferry_terminal", "A couple leaves the check-in hall for the cafe.", "check_in_hall", "cafe"),
])
def test_a_hyphenated_name_is_one_name(read, world, prompt, start, destination):
    g = read(world, prompt).groups[0]
    assert (g.start, g.destination) == (start, destination)


@pytest.mark.parametrize("world,prompt,location", [
    ("tv_studio", "Two presenters wait in make-up while a runner walks to the gallery.", "make_up"),
    ("tv_studio", "A guest sits in make up for ten minutes.", "make_up"),
])
def test_make_up_said_bare_is_the_make_up_room(read, world, prompt, location):
    assert read(world, prompt).groups[0].location == location


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("airport", "Two pilots walk from the check-in hall to the cafe.", "check_in_hall", "cafe"),
    ("hall_of_residence", "A student leaves the sign-in screen for the laundry.", "sign_in_screen", "laundry"),
    ("parcel_depot", "A driver walks from the clocking-in machine to the canteen.", "clocking_in_machine", "canteen"),
    ("tv_studio", "A guest walks from the sign-in desk to the green room.", "sign_in_desk", "green_room"),
    ("tv_studio", "A presenter walks from the canteen to makeup.", "canteen", "make_up"),
    ("warehouse", "A driver leaves goods-in for the canteen.", "goods_in", "canteen"),
])
def test_hyphenated_names_read_already_keep_their_reading(read, world, prompt, start, destination):
    g = read(world, prompt).groups[0]
    assert (g.start, g.destination) == (start, destination)


@pytest.mark.parametrize("world,prompt,destination", [
    ("tv_studio", "A presenter makes her way to the gallery.", "gallery"),
    ("office", "Two engineers make up their minds and walk to the kitchen.", "kitchen"),
])
def test_make_as_a_verb_stays_a_verb(read, world, prompt, destination):
    assert read(world, prompt).groups[0].destination == destination
