"""Place classes of round 13b, each with sentences of its own over at least two worlds (none from the
understanding sets): two places said against each other that the world keeps in one room ("take the
stairs, not the lifts"); a kind before a building word or a shop that the world's place of that head does
not have ("the garden centre" against the travel centre, "the pet shop" against the coffee shop); leaving
one place for another; a purpose's list of things with an article in it."""

from __future__ import annotations

import pytest

# ---- A. two places said against each other in one room: that room's fixtures ----------------------


@pytest.mark.parametrize("world,prompt,place,avoid", [
    ("hospital", "Two porters take the lifts rather than the stairs.", "elevator_1", ("stairwell",)),
    ("hospital", "Five cleaners take the stairs and not the lifts.", "stairwell", ("elevator_1", "elevator_2")),
    ("library", "A student takes the stairs, not the lift.", "stairwell", ("lift_1",)),
    ("university", "Three lecturers take the stairs instead of the lifts.", "staircase", ("lift_a", "lift_b")),
])
def test_places_said_against_each_other_in_one_room_are_its_fixtures(read, world, prompt, place, avoid):
    group = read(world, prompt).groups[0]
    assert (group.destination, group.avoid, group.via) == (place, avoid, ())


@pytest.mark.parametrize("world,prompt,destination,via", [
    ("hospital", "A nurse takes the lift.", "elevator_hall", ()),  # the way taken, with nowhere else to go
    ("hotel", "A guest takes the lift.", "lift_lobby", ()),
    ("hospital", "Two porters take the stairs to the pharmacy.", "pharmacy", ("elevator_hall",)),
    ("hospital", "Three visitors walk to the stairs.", "elevator_hall", ()),  # no contrast: the room
])
def test_a_way_taken_is_where_they_go_only_with_no_other_place(read, world, prompt, destination, via):
    group = read(world, prompt).groups[0]
    assert (group.destination, group.via) == (destination, via)


# ---- B. a kind before a building word or shop that the world's place of that head lacks -------------

@pytest.mark.parametrize("world,prompt,refused", [
    ("station", "A family walks from the café to the garden centre.", "garden centre"),
    ("station", "Two delegates go to the conference centre.", "conference centre"),
    ("supermarket", "A woman walks to the pet shop.", "pet shop"),  # "pet" is tagged an adjective
    ("supermarket", "A boy runs from the bakery to the sweet shop.", "sweet shop"),
    ("mall", "Two kids go from the food court to the pet shop.", "pet shop"),
])
def test_a_kind_the_place_of_that_head_is_not_is_refused(read, world, prompt, refused):
    reading = read(world, prompt)
    assert (refused in reading.unknown_places, reading.groups[0].destination) == (True, None)


@pytest.mark.parametrize("world,prompt,field,place", [
    ("station", "Two backpackers walk to the tourist centre.", "destination", "travel_centre"),  # near "travel"
    ("supermarket", "A woman walks to the coffee shop.", "destination", "cafe"),  # its own modifier
    ("library", "Two students walk to the coffee shop.", "destination", "cafe"),
    ("mall", "A boy walks from the computer shop to the food court.", "start", "electronics_store"),
    ("museum", "Some tourists stand in the vast hall.", "location", "great_hall"),  # a look, not a kind
])
def test_a_modifier_near_the_place_or_a_look_keeps_it(read, world, prompt, field, place):
    reading = read(world, prompt)
    assert (getattr(reading.groups[0], field), reading.unknown_places) == (place, ())


@pytest.mark.parametrize("world,prompt", [
    ("supermarket", "A man walks from the deli to the shopping centre."),
    ("mall", "Two teenagers walk to the shopping centre."),
])
def test_a_building_compound_that_is_the_building_names_no_room(read, world, prompt):
    reading = read(world, prompt)
    assert (reading.groups[0].destination, reading.unknown_places) == (None, ())


# ---- C. leaving one place for another ---------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination,refused", [
    ("museum", "Two guards leave the café for the planetarium.", "cafe", None, ("planetarium",)),
    ("hospital", "A nurse leaves the ward for the canteen.", "ward_a", "cafeteria", ()),
    ("station", "A family leaves the waiting room for the platform.", "waiting_room", "platform_1", ()),
])
def test_leaving_a_place_for_another_goes_there(read, world, prompt, start, destination, refused):
    reading = read(world, prompt)
    group = reading.groups[0]
    assert (group.start, group.destination, group.purpose, reading.unknown_places) == \
        (start, destination, None, refused)


@pytest.mark.parametrize("world,prompt", [
    ("museum", "A group of kids heads for the planetarium."),
    ("mall", "A dad makes a beeline for the pet shop."),
])
def test_a_place_headed_for_that_the_world_lacks_is_no_purpose(read, world, prompt):
    reading = read(world, prompt)
    assert (reading.groups[0].purpose, reading.groups[0].destination, len(reading.unknown_places)) == (None, None, 1)


def test_leaving_for_a_meal_is_still_what_for(read):
    assert read("office", "Three developers leave the kitchen for lunch.").groups[0].purpose == "for lunch"


# ---- D. a purpose's list of things, items with an article ------------------------------------------

@pytest.mark.parametrize("world,prompt,purpose", [
    ("mall", "A man walks from the cinema to buy plasters, paracetamol and a tube of cream.",
     "to buy plasters, paracetamol and a tube of cream"),
    ("supermarket", "A man goes to buy bread, milk and a bag of apples, while two staff wait at the tills.",
     "to buy bread, milk and a bag of apples"),
    ("hospital", "A dad walks over to buy a coffee and a sandwich at the cafeteria.",
     "to buy a coffee and a sandwich"),
])
def test_a_purpose_keeps_its_whole_list_of_things(read, world, prompt, purpose):
    assert read(world, prompt).groups[0].purpose == purpose


def test_a_list_stops_at_people_of_a_clause_of_their_own(read):
    reading = read("supermarket", "A man goes to buy a loaf and two nurses walk to the café.")
    assert [(g.purpose, g.destination) for g in reading.groups] == [("to buy a loaf", "bakery_counter"),
                                                                     (None, "cafe")]


# ---- E. a place said by what it is next to: the other place is no start -----------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("library", "A student goes to the group study room next to the café.", "group_study_1"),
    ("hospital", "A visitor goes to the chairs next to the pharmacy.", "pharmacy_waiting_chairs"),
    ("airport", "Two men walk to the café near the gates.", "cafe"),
])
def test_a_place_next_to_another_gives_no_start(read, world, prompt, destination):
    group = read(world, prompt).groups[0]
    assert (group.start, group.destination) == (None, destination)


def test_a_start_said_by_what_it_is_near_stays_the_start(read):
    reading = read("airport", "Two men walk from the café near the gates to security.")
    assert (reading.groups[0].start, reading.groups[0].destination) == ("cafe", "security_checkpoint")


# ---- F. "to" and a numbered place of a series, whatever the parser makes its first word ------------

@pytest.mark.parametrize("world,prompt,refused", [
    ("university", "Two students walk to lecture theatre 3.", "lecture theatre 3"),
    ("office", "A developer walks to meeting room 7.", "meeting room 7"),
])
def test_a_numbered_place_the_world_lacks_after_to_is_refused(read, world, prompt, refused):
    reading = read(world, prompt)
    assert (reading.unknown_places, reading.groups[0].purpose) == ((refused,), None)


def test_a_numbered_place_the_world_has_after_to_is_where_they_go(read):
    assert read("university", "A lecturer hurries to lecture theatre 2.").groups[0].destination == "lecture_theatre_2"
