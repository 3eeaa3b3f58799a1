"""Place classes of round 43 (places said by what is done there), each with sentences of its own over at
least two worlds (none from the understanding sets):
1. a place said by what is done there in words related to its description's, not the same words ("where
   the clay is fired" of a room "where the pottery classes are held ... and the kiln", "where the watch
   sleeps" of "the dormitory ... with a row of bunks"), and after "wherever" as after "where".
2. two places said so in one sentence ("from where X to where Y") are two places: the first clause ends at
   "to where"; and "into the place where ..." is a place, not a state like "falls into place"."""

from __future__ import annotations

import pytest


# ---- 1. what is done there, in related words ----------------------------------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("community_centre", "Four retirees drift over to where the clay is fired.", "craft_room"),
    ("community_centre", "A volunteer heads to wherever the pottery classes are held.", "craft_room"),
    ("fire_station", "Two firefighters stroll to where the watch sleeps.", "dormitory"),
    ("ski_lodge", "A skier limps over to where hurt skiers get patched up.", "first_aid_room"),
    ("care_home", "A carer walks to where residents eat.", "dining_room"),
    ("aquarium", "Two keepers walk over to wherever the water is filtered.", "life_support_room"),
    ("art_gallery", "A conservator walks from the shop to wherever the paintings are kept.", "art_store"),
    ("primary_school", "Two pupils walk to wherever the dinners are served.", "dining_hall"),
])
def test_a_place_said_by_what_is_done_there_in_related_words(read, world, prompt, destination):
    group = read(world, prompt).groups[0]
    assert group.destination == destination


@pytest.mark.parametrize("world,prompt,destination", [
    ("hotel", "A room attendant carries sheets to where the linen gets laundered.", "laundry"),
    ("hall_of_residence", "Two students lug their bags to where the clothes get laundered.", "laundry"),
    ("ski_lodge", "A skier limps to where injuries get treated.", "first_aid_room"),
    ("art_gallery", "A porter carries a crate to where the paintings are stored.", "art_store"),
    ("youth_hostel", "Three backpackers go to where the meals get cooked.", "guest_kitchen"),
    ("hotel", "A waiter walks to where the food gets cooked.", "kitchen"),
    ("youth_hostel", "A warden walks to where the backpackers eat.", "dining_room"),
])
def test_a_place_said_by_what_is_done_there_in_its_own_words_keeps_its_reading(read, world, prompt, destination):
    (group,) = read(world, prompt).groups
    assert group.destination == destination


# ---- 2. two such places in one sentence; "into the place where" -------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hotel", "A maid walks from the place where the linen is washed to where breakfast is served.",
     "laundry", "restaurant"),
    ("hall_of_residence", "A student walks from where the clothes get washed to where the bikes are kept.",
     "laundry", "bike_store"),
    ("youth_hostel", "A guest wanders from where the meals get cooked to where breakfast is served.",
     "guest_kitchen", "breakfast_counter"),
    ("aquarium", "A keeper walks out of the staff corridor into the place where the water gets filtered.",
     "staff_corridor", "life_support_room"),
])
def test_from_where_to_where_are_two_places(read, world, prompt, start, destination):
    (group,) = read(world, prompt).groups
    assert (group.start, group.destination) == (start, destination)


@pytest.mark.parametrize("world,prompt,destination", [
    ("aquarium", "A keeper walks into the place where the tank water gets filtered.", "life_support_room"),
    ("hotel", "A maid ducks into the place where the linen is washed.", "laundry"),
    ("hall_of_residence", "Two students wander into the place where the clothes get washed.", "laundry"),
    ("ski_lodge", "A patroller ducks into the place where people rent skis.", "ski_hire"),
])
def test_into_the_place_where_is_a_place(read, world, prompt, destination):
    (group,) = read(world, prompt).groups
    assert group.intent == "walk" and group.destination == destination


@pytest.mark.parametrize("world,prompt", [
    ("town_hall", "The mayor falls into place behind the councillors."),
    ("hotel", "A porter bursts into laughter in the lobby."),
])
def test_into_a_state_stays_no_place(read, world, prompt):
    group = read(world, prompt).groups[0]
    assert group.destination is None
