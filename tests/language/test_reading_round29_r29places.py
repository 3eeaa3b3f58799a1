"""Round 29 of the reader's places: a "where" clause whose verb lists several things ("where they sell
tropical fish and rabbits") is read from all of them, the room that holds them, not one fixture; the
subject of a "where" clause after a place, with a noun before its head ("where the pottery classes are
held"), only describes the place and is no group; being powdered, styled or having one's face done is
what is done in a make-up room."""

import pytest


# ---- 1. a where clause listing things: the room holding them ----------------------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("garden_centre", "Two kids run to where they sell fish and rabbits and their dad follows.", "pet_aquatics"),
    ("garden_centre", "A pensioner heads over to where they sell tropical fish and pet food.", "pet_aquatics"),
    ("mall", "A teenager walks from the food court to where they sell trainers and hoodies.", "clothing_store"),
    ("zoo", "A keeper walks over to where they keep the goats and the pigs.", "childrens_farm"),
])
def test_a_where_clause_listing_things_is_the_room_that_holds_them(read, world, prompt, destination):
    for g in read(world, prompt).groups:
        assert g.destination == destination


@pytest.mark.parametrize("world,prompt,destination", [
    ("zoo", "A family wanders from the cafe over to where they keep the penguins and seals.", "penguin_beach"),
    ("garden_centre", "A boy runs over to where they keep the rabbits.", "small_animal_pens"),
    ("aquarium", "A school group walks over to where they keep the sharks and rays.", "shark_tunnel"),
    ("mall", "Two teens drift over to where they sell phones and headphones.", "electronics_store"),
])
def test_where_clauses_of_one_zone_or_one_thing_keep_their_reading(read, world, prompt, destination):
    assert read(world, prompt).groups[0].destination == destination


# ---- 2. the subject of a where clause with a noun modifier: no group --------------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("community_centre", "A caretaker goes from the foyer to the room where the yoga classes are held.", None),
    ("community_centre", "Two mums walk from the kitchen to the room where pottery classes are held.", None),
    ("sports_centre", "A coach walks to the room where the spin classes are held.", None),
    ("library", "Two students walk to the room where the book club meets.", None),
    ("library", "A volunteer walks to the room where the chess club meets.", None),
])
def test_the_subject_of_a_where_clause_with_a_noun_modifier_is_no_group(read, world, prompt, destination):
    assert len(read(world, prompt).groups) == 1


@pytest.mark.parametrize("world,prompt,count", [
    ("community_centre", "A caretaker goes to the room where the children wait.", 1),
    ("hospital", "A nurse walks from the ward to the room where the antenatal classes are held.", 1),
    ("mall", "Three security guards wait where the food court tables are.", 1),
    ("community_centre", "A yoga class waits in the main hall while a caretaker walks to the kitchen.", 2),
])
def test_people_who_are_groups_stay_groups(read, world, prompt, count):
    assert len(read(world, prompt).groups) == count


# ---- 3. being powdered, styled or having one's face done: the make-up room ---------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("tv_studio", "A presenter walks from the green room to the room where guests get their faces powdered.", "make_up"),
    ("tv_studio", "A runner walks from the canteen to the room where guests are powdered.", "make_up"),
    ("tv_studio", "Two guests head over to the room where contestants get their faces done.", "make_up"),
    ("tv_studio", "A producer walks from reception to where guests have their hair done.", "make_up"),
])
def test_being_powdered_or_styled_is_done_in_the_make_up_room(read, world, prompt, destination):
    assert read(world, prompt).groups[0].destination == destination


# ---- 4. people counted after a preposition, and a handheld device: no place to refuse ----------------------

@pytest.mark.parametrize("world,prompt", [
    ("warehouse", "The robot weaves through a dozen pickers in the aisles."),
    ("warehouse", "The robot threads its way through twenty-odd loaders to reach the dispatch bay."),
    ("parcel_depot", "The robot edges past thirty-odd sorters on the sorting floor."),
    ("supermarket", "The robot squeezes through a dozen shelf stackers to reach the tills."),
])
def test_people_counted_after_a_preposition_are_no_unknown_place(read, world, prompt):
    assert read(world, prompt).unknown_places == ()


@pytest.mark.parametrize("world,prompt", [
    ("mall", "Two teens trail the robot, filming it on a phone."),
    ("museum", "A student wanders round the gallery taking photos on a tablet."),
    ("hospital", "A visitor waits in the cafeteria, chatting on a mobile."),
    ("zoo", "A dad films the penguins on a camera."),
])
def test_a_handheld_device_is_no_unknown_place(read, world, prompt):
    assert read(world, prompt).unknown_places == ()


@pytest.mark.parametrize("world,prompt,unknown", [
    ("mall", "A cleaner walks through the ball pit.", "ball pit"),
    ("warehouse", "Two pickers walk through the staff gym.", "staff gym"),
])
def test_places_the_world_lacks_after_through_are_still_refused(read, world, prompt, unknown):
    assert unknown in read(world, prompt).unknown_places
