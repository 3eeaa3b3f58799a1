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


# ---- a named kind of room for sport the world lacks: refused, though a hall is near in meaning -----------

@pytest.mark.parametrize("world,prompt,unknown", [
    ("community_centre", "Eight lads with footballs walk from the foyer to the sports hall.", "sports hall"),
    ("community_centre", "Two coaches carry nets from the kitchen to the sports hall.", "sports hall"),
    ("cathedral", "A verger walks from the nave to the sports hall.", "sports hall"),
])
def test_a_sport_room_the_world_lacks_is_refused(read, world, prompt, unknown):
    assert unknown in read(world, prompt).unknown_places


@pytest.mark.parametrize("world,prompt,unknown", [
    ("community_centre", "Two mums head from the kitchen to the gym.", "gym"),
    ("office", "A manager walks from the open office to the gym.", "gym"),
    ("residential", "Dad goes from the kitchen to the swimming pool.", "swimming pool"),
    ("courthouse", "Two ushers walk from the lobby to the squash court.", "squash court"),
])
def test_other_sport_rooms_the_world_lacks_stay_refused(read, world, prompt, unknown):
    assert unknown in read(world, prompt).unknown_places


@pytest.mark.parametrize("world,prompt,destination", [
    ("community_centre", "Eight lads walk from the foyer to the main hall.", "main_hall"),
    ("primary_school", "A teacher walks from the staff room to the sports hall.", "school_hall"),
])
def test_halls_the_world_has_are_still_read(read, world, prompt, destination):
    reading = read(world, prompt)
    assert reading.unknown_places == () and reading.groups[0].destination == destination
