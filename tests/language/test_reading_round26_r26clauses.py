"""Clause classes of round 26, each with sentences of its own over at least two worlds (none from the
understanding sets): a body of people coming down on a place ("descends on", "converge upon"); a crowd
piling out onto a place, which is no evacuation unless something is urgent; a count in apposition with
a describing phrase ("the hen party, a dozen women in pink sashes, ..."); a fronted with-phrase that
places a second person ("With Nan at the ticket desk, ..."); the robot showing people round a place."""

from __future__ import annotations

import pytest


# ---- 1. coming down on a place: walking there ---------------------------------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("mall", "A coachload of pensioners descends on the food court.", "food_court"),
    ("station", "Twenty commuters converge on the cafe.", "cafe"),
    ("library", "A class of students descends upon the reading room.", "reading_room"),
    ("zoo", "A school party swoops on the gift shop.", "gift_shop"),
    ("hospital", "Three junior doctors converge on the cafeteria for lunch.", "cafeteria"),
])
def test_coming_down_on_a_place_walks_there(read, world, prompt, destination):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.destination, g.location) == ("walk", destination, None)


def test_closing_in_on_the_robot_is_still_about_the_robot(read):
    (g,) = read("mall", "Kids close in on the robot in the food court.").groups
    assert (g.intent, g.location) == ("robot", "food_court")


# ---- 2. piling out onto a place: a crowd leaving, no emergency ------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("mall", "The stag party piles out of the cinema lobby into the food court.", "cinema_lobby", "food_court"),
    ("station", "Eleven lads pile out of the cafe onto platform 2.", "cafe", "platform_2"),
    ("zoo", "A coach party piles out of the gift shop into the cafe.", "gift_shop", "cafe"),
    ("library", "Ten students pile out of the seminar room into the cafe.", "seminar_room", "cafe"),
])
def test_piling_out_onto_a_place_walks_there(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.start, g.destination) == ("walk", start, destination)


@pytest.mark.parametrize("world,prompt", [
    ("mall", "Fire! Twenty shoppers pile out of the toy store into the main atrium."),
    ("hospital", "Smoke fills the ward and the nurses pile out through the main corridor."),
    ("zoo", "Ten visitors pile out of the reptile house."),
])
def test_piling_out_in_an_emergency_or_with_nowhere_said_still_evacuates(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.intent == "evacuate"


# ---- 3. a count in apposition with a describing phrase ----------------------------------------------

@pytest.mark.parametrize("world,prompt,count,intent,place", [
    ("mall", "The hen party, a dozen women in pink sashes, piles into the food court.", 12, "walk", "food_court"),
    ("station", "The rugby team, fifteen men in muddy kit, waits on platform 1.", 15, "wait", "platform_1"),
    ("zoo", "The school party, 25 children in hi-vis vests, troops into the reptile house.", 25, "walk",
     "reptile_house"),
    ("library", "The book club, nine pensioners with their novels, meets in the seminar room.", 9, "converse",
     "seminar_room"),
    ("hospital", "The choir, twenty singers in red robes, files into the main waiting room.", 20, "walk",
     "main_waiting_room"),
])
def test_an_apposed_count_with_a_description_is_the_group_before(read, world, prompt, count, intent, place):
    (g,) = read(world, prompt).groups
    assert (g.count.value, g.intent, g.destination or g.location) == (count, intent, place)


# ---- 4. a fronted with-phrase placing a second person ---------------------------------------------------

@pytest.mark.parametrize("world,prompt,first,second", [
    ("museum", "With Nan at the ticket desk, the twins slump on a bench.", ("wait", "ticket_desk"),
     ("wait", "great_hall_benches")),
    ("mall", "With two guards by the south entrance, shoppers queue at the pharmacy.",
     ("wait", "south_entrance_hall"), ("queue", "pharmacy")),
    ("station", "With Grandad in the waiting room, two boys wander the concourse.", ("wait", "waiting_room"),
     ("wander", "concourse")),
    ("library", "With a librarian at the lending desk, ten students queue in the lending hall.",
     ("wait", "issue_desk"), ("queue", "lending_hall")),
    ("zoo", "With Mum in the gift shop, three kids watch the penguins at the penguin beach.",
     ("wait", "gift_shop"), ("wait", "penguin_beach")),
    ("hospital", "With a porter by the lifts, two visitors queue at the pharmacy.",
     ("wait", "elevator_hall"), ("queue", "pharmacy")),
])
def test_a_with_phrase_places_a_person_of_its_own(read, world, prompt, first, second):
    a, b = read(world, prompt).groups
    assert ((a.intent, a.location), (b.intent, b.location)) == (first, second)


@pytest.mark.parametrize("world,prompt,intent,place", [
    ("mall", "With coffee in hand, two girls wander the west mall.", "wander", "west_mall"),
    ("station", "With their kids in tow, two dads walk to the cafe.", "walk", "cafe"),
])
def test_a_with_phrase_of_things_or_companions_adds_nobody(read, world, prompt, intent, place):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.destination or g.location) == (intent, place)


# ---- 5. the robot showing people round a place ------------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("museum", "The robot shows visitors round the great hall.", "great_hall"),
    ("hospital", "The robot shows two new nurses round the main waiting room.", "main_waiting_room"),
    ("library", "The robot shows a class of students around the reading room.", "reading_room"),
    ("zoo", "The robot shows a family round the reptile house.", "reptile_house"),
    ("mall", "The robot shows the new cleaners around the food court.", "food_court"),
])
def test_the_robot_showing_people_round_a_place_takes_them_through_it(read, world, prompt, place):
    reading = read(world, prompt)
    (g,) = reading.groups
    assert reading.robot is not None
    assert (reading.robot.task, reading.robot.via, g.robot_interaction) == ("cross", (place,), "follow")


@pytest.mark.parametrize("world,prompt,place", [
    ("mall", "The robot waits in the food court.", "food_court"),
    ("museum", "The robot shows the exhibits in the great hall.", "great_hall"),
])
def test_the_robot_waiting_or_showing_things_still_waits(read, world, prompt, place):
    robot = read(world, prompt).robot
    assert robot is not None and (robot.task, robot.location) == ("wait", place)


# ---- 6. one person's verb in a later clause of a list, taken for a plural noun --------------------------

@pytest.mark.parametrize("world,prompt,groups", [
    ("mall", "A cleaner mops the food court, a courier wheels parcels from the supermarket to the toy store, and "
             "a busker plays in the main atrium.", 3),
    ("station", "A porter sweeps the concourse, a guard walks from the cafe to platform 2, and a busker sings in "
                "the ticket hall.", 3),
    ("station", "A guard walks from platform 2 to the cafe and a busker sings in the ticket hall.", 2),
    ("mall", "A guard walks to the toy store and a busker sings in the main atrium.", 2),
    ("library", "A student reads in the reading room and a courier wheels boxes from the sorting room to the "
                "lending hall.", 2),
])
def test_a_later_clauses_person_and_verb_are_read(read, world, prompt, groups):
    assert len(read(world, prompt).groups) == groups


def test_a_list_of_places_after_and_adds_nobody(read):
    (g,) = read("mall", "Two girls walk past the bookshop and the coffee shops in the main atrium.").groups
    assert g.count.value == 2
