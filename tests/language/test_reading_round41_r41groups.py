"""Group classes of round 41, each with sentences of its own over at least two worlds (none from the
understanding sets):
1. one person named by a word the reader does not know as a person, said with a describing participle
   ("the smiling clown walks") or with a verb the tagger takes for a plural noun ("a year-ten ducks out of
   X"), is one person, not a vague crowd left to the model.
2. what people wear when the world also calls a place by it ("tots in armbands", "drivers in helmets",
   "scientists in gowns") is no place they start from or are in."""

from __future__ import annotations

import pytest


# ---- 1. one unknown person word is one person ----------------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("office", "The smiling clown walks to the kitchen."),
    ("mall", "The waving clown walks to the fountain."),
    ("office", "A sixth-former runs out of the kitchen."),
    ("hospital", "A sixth-former runs out of the cafeteria."),
    ("mall", "A year-ten ducks out of the toy shop."),
    ("station", "A year-eleven nips out of the cafe toward platform 2."),
    ("care_home", "A year-nine dashes out of the lounge."),
    ("care_home", "The visiting hairdresser makes her way from reception to the lounge."),
])
def test_one_unknown_person_word_is_one_person(read, world, prompt):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value) == ("exact", 1)


# ---- guards: things and places that open a sentence are no person --------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("office", "The flashing light blinks in the kitchen."),
    ("office", "The waiting room fills up."),
    ("mall", "The revolving door spins."),
    ("care_home", "The hair salon opens at nine."),
])
def test_things_opening_a_sentence_stay_a_guessed_crowd(read, world, prompt):
    (group,) = read(world, prompt).groups
    assert group.count.kind == "vague"


@pytest.mark.parametrize("world,prompt,value", [
    ("hospital", "The yawning locum shuffles to the cafeteria.", 1),
    ("mall", "The beaming magician strolls out of the toy shop.", 1),
    ("care_home", "The visiting barber makes his way from reception to the lounge.", 1),
    ("office", "Three smiling clowns walk to the kitchen.", 3),
])
def test_people_the_reader_knew_keep_their_count(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value) == ("exact", value)


# ---- 2. worn things that are also a place's words ------------------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("swimming_baths", "Nine tots in armbands troop from group changing down to the learner pool.", "group_changing", "teaching_pool"),
    ("swimming_baths", "Six kids in goggles splash from group changing to the learner pool.", "group_changing", "teaching_pool"),
    ("karting_centre", "Four drivers in helmets walk from the kit room to the track.", "kit_room", "track"),
    ("karting_centre", "Eight teenagers in overalls wander from reception to the track.", "reception", "track"),
    ("playhouse", "Five actors in costumes hurry from the green room to the stage.", "green_room", "stage"),
    ("research_lab_building", "Three scientists in gowns walk from the lab to the canteen.", "wet_lab_1", None),
])
def test_worn_things_are_no_place(read, world, prompt, start, destination):
    (group,) = read(world, prompt).groups
    assert (group.start, group.destination) == (start, destination)


@pytest.mark.parametrize("world,prompt,location", [
    ("karting_centre", "Two marshals wait in the kit room.", "kit_room"),
    ("karting_centre", "A mechanic in the helmet racks waves.", "helmet_racks"),
    ("playhouse", "Two actors in costume rails giggle.", "costume_rails"),
    ("fire_station", "A firefighter waits in the kit room.", "kit_room"),
])
def test_places_named_by_worn_words_stay_places(read, world, prompt, location):
    (group,) = read(world, prompt).groups
    assert group.location == location
