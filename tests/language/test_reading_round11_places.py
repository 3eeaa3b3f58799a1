"""Place classes of round 11, each with sentences of its own over at least two worlds (none from the
understanding sets): a thing of a room said with the room ("the restaurant counter", "the door of the
gym"); a place said and then excluded ("the stairs, not the lifts")."""

from __future__ import annotations

import pytest


def place_of(group):
    return group.destination or group.location or group.start


# ---- A. a thing of a room said with the room -------------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("hotel", "A waiter stands at the restaurant counter.", "breakfast_buffet"),
    ("hotel", "Two guests wait by the door of the bar.", "bar_door"),
    ("hotel", "Three guests queue at the spa desk.", "spa_reception"),
    ("sports_centre", "A coach waits by the door of the gym.", "gym_door"),
    ("sports_centre", "A parent stands at the door of the first aid room.", "first_aid_door"),
    ("station", "A guard waits by the door of the waiting room.", "waiting_room_door"),
    ("library", "Four students sit round the sorting room table.", "sorting_table"),
])
def test_a_thing_of_a_room_said_with_the_room(read, world, prompt, place):
    assert place_of(read(world, prompt).groups[0]) == place


# ---- B. a place said, then another of its kind excluded ---------------------------------------------

@pytest.mark.parametrize("world,prompt,place,avoided", [
    ("station", "Make eight people wait on the benches in the waiting room, not the ones on the concourse.",
     "waiting_benches", "concourse_benches"),
    ("station", "Six people sit on the benches on the concourse, not the ones in the waiting room.",
     "concourse_benches", "waiting_benches"),
    ("hotel", "Four guests sit at the tables in the restaurant, not the ones in the bar.", "restaurant_tables", "bar_tables"),
    ("hotel", "Two guests sit at the tables in the bar, not the ones in the ballroom.", "bar_tables", "banquet_tables"),
    ("library", "Five students sit at the tables in the reading room, not the ones in the cafe.",
     "reading_tables", "cafe_tables"),
    ("library", "Three readers sit at the tables in the cafe, not the ones in the reading room.",
     "cafe_tables", "reading_tables"),
])
def test_the_ones_excluded_are_not_chosen(read, world, prompt, place, avoided):
    group = read(world, prompt).groups[0]
    assert (place_of(group), group.avoid) == (place, (avoided,))


# ---- C. chat after a place's whole name ends the place ----------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("hotel", "~20 ppl sat in lobby waitin 4 taxis", "lobby"),
    ("hotel", "5 guests in bar waitin 4 dinner", "bar"),
    ("hotel", "6 ppl in restaurant eatin", "restaurant"),
    ("sports_centre", "10 ppl sat in cafe waitin 4 class", "cafe"),
    ("sports_centre", "3 kids in foyer chattin", "foyer"),
    ("library", "4 students in reading room waitin 4 the librarian", "reading_room"),
])
def test_chat_after_a_whole_name_is_no_part_of_the_place(read, world, prompt, place):
    reading = read(world, prompt)
    assert (reading.groups[0].location, reading.unknown_places) == (place, ())


# ---- D. a kind of room the world lacks, even when its words hold a person or a verb -----------------

@pytest.mark.parametrize("world,prompt,refused", [
    ("station", "Two mums walk to the baby changing room.", "baby changing room"),
    ("hospital", "A dad carries his son to the baby changing room.", "baby changing room"),
    ("hotel", "Two mums walk to the baby changing room.", "baby changing room"),
    ("sports_centre", "A mum takes her toddler to the baby change room.", "baby change room"),
    ("library", "A man walks to the first aid room.", "first aid room"),
])
def test_a_kind_of_room_the_world_lacks_is_refused(read, world, prompt, refused):
    assert read(world, prompt).unknown_places == (refused,)


def test_a_kind_of_room_the_world_has_is_read(read):
    assert read("sports_centre", "A man walks to the first aid room.").groups[0].destination == "first_aid_room"


# ---- E. a purpose is done at the fixture of the room that serves it ----------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("station", "A commuter leaves the platform to grab a coffee.", "cafe_counter"),
    ("station", "Two travellers leave the waiting room to get a coffee.", "cafe_counter"),
    ("library", "A student leaves the reading room to get a coffee.", "cafe_counter"),
    ("library", "A librarian pops out of the stacks to get a coffee.", "cafe_counter"),
    ("sports_centre", "After her swim a woman heads off to get a coffee.", "cafe_counter"),
])
def test_a_purpose_is_done_at_the_counter_that_serves_it(read, world, prompt, place):
    assert read(world, prompt).groups[0].destination == place


# ---- F. a thing given by what it is next to -------------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("station", "Two men sit on the bench next to the water fountain.", "waiting_benches"),
    ("hotel", "A couple sit at the table next to the buffet.", "restaurant_tables"),
    ("library", "A student sits at the table next to the reference shelves.", "reading_tables"),
    ("library", "Two readers sit at the tables near the cafe counter.", "cafe_tables"),
    ("sports_centre", "A man sits on the bench beside the pool.", "poolside_bench"),
])
def test_a_thing_by_what_it_is_next_to(read, world, prompt, place):
    assert place_of(read(world, prompt).groups[0]) == place
