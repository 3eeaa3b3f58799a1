"""Classes of round 43 (group boundaries), with sentences of their own over several worlds (none from the
understanding sets):

1. a plural group said with no number, then a collective or vague share "of them" set off by commas ("teenagers
   in hoodies, a whole gang of them, loiter ..."): one group, as many as the apposition says, not a second
   group or a subset (language/apposed_collectives.py);
2. a person met first ("finds an old man in the corridor", "greets Mrs Cole at the entrance", "links arms
   with Gramps") and then taken along by a pronoun ("and walks him to ..."): the second group, following the
   mover, from where they met (language/met_then_moved.py)."""

from __future__ import annotations

import pytest


# ---- 1. a collective "of them" in apposition says how many the group before is ------------------------------

@pytest.mark.parametrize("world,prompt,intent,low,high", [
    ("mall", "Teenagers in hoodies, a whole gang of them, loiter by the fountain.", "wait", 3, 5),
    ("museum", "Pupils in blazers, a whole class of them, troop into the main hall.", "walk", 10, 20),
    ("zoo", "Schoolchildren, a noisy bunch of them, crowd round the penguin pool.", "wait", 3, 5),
    ("hospital", "The relatives, a whole crowd of them, wait outside the ward.", "wait", 15, 30),
    ("office", "Interns, a small group of them, huddle by the coffee machine.", "wait", 3, 5),
    ("airport", "Travellers, a family of them, wait by gate A2.", "wait", 3, 4),
    ("hospital", "Worried relatives, a handful of them, wait outside the ward.", "wait", 3, 5),
])
def test_a_collective_of_them_in_apposition_is_the_group_before(read, world, prompt, intent, low, high):
    (group,) = read(world, prompt).groups
    assert group.intent == intent
    assert group.relation is None
    assert low <= group.count.value <= high


@pytest.mark.parametrize("world,prompt,place,low,high", [
    ("mall", "Shoppers queue at the tills, a whole crowd of them.", "checkout_counter", 15, 30),
    ("hospital", "Visitors wait in the lobby, a small group of them.", "entrance_lobby", 3, 5),
])
def test_a_collective_of_them_said_last_is_how_many(read, world, prompt, place, low, high):
    (group,) = read(world, prompt).groups
    assert group.location == place
    assert low <= group.count.value <= high


# ---- guards: counts in apposition and subsets "of them" keep their reading -------------------------------------

@pytest.mark.parametrize("world,prompt,count", [
    ("museum", "The pupils, about thirty of them, troop into the main hall.", 30),
    ("mall", "The shoppers, some forty of them, queue at the tills.", 40),
])
def test_counts_in_apposition_keep_their_reading(read, world, prompt, count):
    (group,) = read(world, prompt).groups
    assert group.count.value == count


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "Ten nurses, two of them students, walk to the ward."),
    ("hospital", "Visitors wait in the lobby; a group of them walk to the cafe."),
    ("mall", "Teenagers loiter by the fountain, and a gang of them walk to the cinema."),
])
def test_a_part_of_them_with_its_own_clause_stays_a_group(read, world, prompt):
    assert len(read(world, prompt).groups) == 2


# ---- 2. a person met, then taken along by a pronoun ------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "A nurse finds an old man in the corridor and walks him to the pharmacy.", "main_corridor", "pharmacy"),
    ("airport", "A steward meets an elderly passenger at check-in and escorts her to gate A2.", "check_in_hall",
     "gate_a2"),
    ("mall", "A guard spots a lost child by the fountain and leads him to the information desk.", "fountain",
     "information_desk"),
    ("residential", "Mum wakes the twins and leads them to the kitchen.", None, "kitchen"),
    ("hall_of_residence", "A warden finds a lost fresher in the laundry and walks her back to reception.", "laundry",
     "reception"),
    ("museum", "Dr Amis greets Mrs Cole at the entrance and takes her to the main hall.", "entrance_hall",
     "great_hall"),
])
def test_a_person_met_then_taken_along_is_the_second_group(read, world, prompt, start, destination):
    mover, moved = read(world, prompt).groups
    assert mover.intent == "walk" and moved.intent == "follow"
    assert mover.destination == moved.destination == destination
    assert mover.start == moved.start == start


# ---- guards: things found and taken, and people already taken along, keep their reading ------------------------

@pytest.mark.parametrize("world,prompt,groups", [
    ("mall", "A guard finds a seat and walks to the food court.", 1),
    ("hospital", "A nurse finds a wheelchair and takes it to the ward.", 1),
    ("mall", "A dad picks up his toddler and carries him to the food court.", 1),
    ("residential", "Mum takes Gran by the hand and leads her from the kitchen to the garden.", 2),
    ("hospital", "A daughter takes her dad's arm and walks him to the cafeteria.", 2),
])
def test_things_found_and_people_taken_keep_their_reading(read, world, prompt, groups):
    assert len(read(world, prompt).groups) == groups


# ---- 3. a fronted whole said with a bare number, and its part "a pair", "a trio" ---------------------------------

@pytest.mark.parametrize("world,prompt,whole,part", [
    ("hospital", "Of twelve nurses on the ward, a pair head to the cafeteria.", 12, 2),
    ("mall", "Of twenty shoppers in the food court, a trio walk to the cinema.", 20, 3),
    ("airport", "Of six pilots in the lounge, a couple walk to gate A2.", 6, 2),
    ("office", "Of 8 developers at their desks, a trio go to the kitchen.", 8, 3),
    ("museum", "Of thirty pupils in the main hall, a foursome wander off to the gift shop.", 30, 4),
])
def test_a_bare_numbered_whole_said_first_keeps_its_part(read, world, prompt, whole, part):
    first, second = read(world, prompt).groups
    assert first.count.value == whole
    assert second.count.value == part and second.relation == "subset_of:0"
    assert second.intent == "walk"


# ---- guards: fronted wholes read already, and "Of course", keep their reading ------------------------------------

@pytest.mark.parametrize("world,prompt,counts", [
    ("mall", "Of course, two guards walk to the fountain.", [2]),
    ("hospital", "Of twelve nurses on the ward, two head to the cafeteria.", [12, 2]),
    ("hospital", "Of the twelve nurses on the ward, a pair head to the cafeteria.", [12, 2]),
    ("airport", "Of six pilots in the lounge, one walks to gate A2.", [6, 1]),
])
def test_fronted_wholes_already_read_keep_their_reading(read, world, prompt, counts):
    assert [g.count.value for g in read(world, prompt).groups] == counts
