"""Round 7 on people and clauses, each class with sentences of its own over at least two worlds (none
from the understanding sets): a whole said before its part ("Of the twelve nurses on the ward, two
..."); a person carried, pushed or escorted, named through a possessive or a role; queue phrasings;
the robot's own motion verbs; approximations kept per count; a verb that takes a place as its object."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt


def read(worlds, world, prompt):
    reading = read_prompt(prompt, worlds[world])
    assert reading.unknown_places == (), reading.unknown_places
    return reading


# ---- 1. a whole said before its part -----------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,whole,where,part,intent,destination", [
    ("hospital", "Of the 12 nurses on the ward, two go to the pharmacy.", 12, "ward_a", 2, "walk", "pharmacy"),
    ("station", "Out of forty passengers on platform 1, ten walk to the exit.", 40, "platform_1", 10, "walk",
     "platform_1_exit"),
    ("office", "Of the eight developers at their desks, two head to the kitchen.", 8, "open_plan_office", 2, "walk",
     "kitchen"),
    ("museum", "Of the 25 pupils in the Egyptian gallery, about ten drift off to the cafe.", 25, "egyptian_gallery",
     10, "walk", "cafe"),
    ("airport", "Out of about sixty passengers queuing at security, a dozen give up and go to the cafe.", 60,
     "security_checkpoint", 12, "walk", "cafe"),
])
def test_a_whole_said_first_and_its_part(worlds, world, prompt, whole, where, part, intent, destination):
    g0, g1 = read(worlds, world, prompt).groups
    assert (g0.count.value, g0.location, g0.relation) == (whole, where, None)
    assert (g1.count.value, g1.intent, g1.destination, g1.relation) == (part, intent, destination, "subset_of:0")
    assert g1.label == g0.label


@pytest.mark.parametrize("world,prompt,where", [
    ("hospital", "Of the patients in the waiting room, three go to the pharmacy.", "main_waiting_room"),
    ("residential", "Of the four kids in the living room, two go to the kitchen.", "living_room"),
])
def test_a_whole_with_or_without_a_number_keeps_its_place(worlds, world, prompt, where):
    g0, g1 = read(worlds, world, prompt).groups
    assert g0.location == where and g1.relation == "subset_of:0" and g1.count.value < g0.count.value


@pytest.mark.parametrize("world,prompt", [
    ("office", "Of course, two developers go to the kitchen."),
    ("mall", "Of all days, four shoppers queue at the cinema on Monday."),
])
def test_of_without_people_is_no_whole(worlds, world, prompt):
    groups = read_prompt(prompt, worlds[world]).groups
    assert len(groups) == 1 and groups[0].relation is None


# ---- 2. a person carried, pushed or escorted, named through a possessive or a role -------------------

@pytest.mark.parametrize("world,prompt,leader,carried,start,destination", [
    ("mall", "A mother pushes her baby's pram from the cinema to the food court.", "mother", "baby",
     "cinema_lobby", "food_court"),
    ("station", "A dad pushes his son's buggy from the concourse to platform 2.", "dad", "son", "concourse",
     "platform_2"),
    ("residential", "A friend piggybacks his little sister from the balcony to the living room.", "friend", "sister",
     "balcony", "living_room"),
    ("airport", "A porter wheels the old lady from the check-in hall to gate A1.", "porter", "lady",
     "check_in_hall", "gate_a1"),
    ("museum", "A grandfather carries his granddaughter from the cafe to the dinosaur gallery.", "grandfather",
     "granddaughter", "cafe", "dinosaur_gallery"),
])
def test_the_carried_person_is_a_group_on_the_same_route(worlds, world, prompt, leader, carried, start,
                                                         destination):
    g0, g1 = read(worlds, world, prompt).groups
    assert (g0.label, g0.intent, g0.start, g0.destination, g0.via) == (leader, "walk", start, destination, ())
    assert (g1.label, g1.count.value, g1.intent, g1.start, g1.destination) == (carried, 1, "follow", start,
                                                                               destination)


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "A nurse pushes a wheelchair to radiology."),
    ("office", "Two developers push a trolley from the kitchen to the boardroom."),
])
def test_an_empty_wheelchair_is_no_person_and_no_place(worlds, world, prompt):
    g, = read(worlds, world, prompt).groups
    assert g.via == () and g.intent == "walk"


# ---- 3. queue phrasings -------------------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("hospital", "5 patients in the queue at the pharmacy, 3 more at reception", "pharmacy"),
    ("station", "Ten commuters lined up at the ticket machines.", "ticket_machines"),
    ("hospital", "Five patients waiting their turn at the pharmacy.", "pharmacy"),
    ("museum", "Twelve visitors standing in line for the cloakroom.", "cloakroom"),
    ("office", "Four developers await their turn at the coffee machine.", "coffee_machine"),
    ("residential", "The kids take turns at the bathroom.", "bathroom"),
    ("museum", "Nine tourists in a queue at the ticket desk.", "ticket_desk"),
    ("mall", "Six shoppers queueing up for the cinema.", "cinema_lobby"),
])
def test_queue_phrasings_queue_at_their_place(worlds, world, prompt, location):
    g = read(worlds, world, prompt).groups[0]
    assert (g.intent, g.location) == ("queue", location)


def test_a_place_phrase_after_a_group_is_its_own_not_the_next_groups(worlds):
    g0, g1 = read(worlds, "hospital", "5 patients in the queue at the pharmacy, 3 more at reception").groups
    assert (g0.count.value, g0.location) == (5, "pharmacy")
    assert (g1.count.value, g1.location, g1.relation) == (3, "reception_desk", "more_of:0")


# ---- 4. the robot's own motion verbs ------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,via", [
    ("mall", "Two kids wave at the robot as it glides by.", ()),
    ("office", "A developer watches the robot as it whizzes past.", ()),
    ("museum", "Children point at the robot as it passes.", ()),
    ("office", "Two interns step aside as the robot scoots by.", ()),
    ("hospital", "Three nurses step aside as the robot trundles through the main corridor.", ("main_corridor",)),
    ("airport", "Passengers stare at the robot as it zips along the check-in hall.", ("check_in_hall",)),
])
def test_the_robot_going_by_crosses(worlds, world, prompt, via):
    reading = read(worlds, world, prompt)
    assert reading.robot is not None and (reading.robot.task, reading.robot.via) == ("cross", via)
    assert reading.groups[0].intent == "robot"


@pytest.mark.parametrize("world,prompt", [
    ("residential", "Grandpa waves when the robot comes near."),
    ("hospital", "Two nurses chat while the robot comes closer."),
])
def test_the_robot_coming_near_sets_no_route(worlds, world, prompt):
    assert read(worlds, world, prompt).robot is None


# ---- 5. approximations kept per count ----------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,counts", [
    ("hospital", "In the evening roughly thirty visitors walk to the cafeteria, while two nurses wait at reception.",
     [("approximate", 30), ("exact", 2)]),
    ("mall", "On Saturday some forty shoppers mill around the food court and ten teenagers wait at the cinema.",
     [("approximate", 40), ("exact", 10)]),
    ("airport", "approx 50 passengers queue at security while 3 guards wait at the gate.",
     [("approximate", 50), ("exact", 3)]),
    ("station", "At noon around 60 commuters wait on platform 2.", [("approximate", 60)]),
    ("hospital", "After lunch approximately 12 patients queue at the pharmacy.", [("approximate", 12)]),
    ("office", "At 9 about thirty developers arrive at the open office.", [("approximate", 30)]),
    ("museum", "At opening time 30-ish visitors wait in the entrance hall.", [("approximate", 30)]),
    ("office", "Give or take twenty developers head to the kitchen.", [("approximate", 20)]),
    ("office", "Twenty developers, give or take, head to the kitchen.", [("approximate", 20)]),
    ("hospital", "Forty visitors, or thereabouts, wait in the main waiting room.", [("approximate", 40)]),
    ("airport", "~25 passengers wait at gate A1, and 4 staff stand at the information desk.",
     [("approximate", 25), ("exact", 4)]),
])
def test_each_count_keeps_its_approximation(worlds, world, prompt, counts):
    groups = read(worlds, world, prompt).groups
    assert [(g.count.kind, g.count.value) for g in groups] == counts


# ---- 6. a verb that takes a way through as its object --------------------------------------------------

@pytest.mark.parametrize("world,prompt,via,destination", [
    ("hospital", "Three visitors take the lift to the ICU.", ("elevator_hall",), "intensive_care"),
    ("hospital", "Two porters use the service lift to get to radiology.", ("elevator_hall",), "radiology"),
    ("residential", "Dad uses the back door.", ("back_door",), None),
    ("residential", "The kids use the back door to go out to the garden.", ("back_door",), "balcony"),
    ("mall", "Four shoppers use the side entrance.", ("south_entrance_hall",), None),
])
def test_the_way_taken_is_passed_through(worlds, world, prompt, via, destination):
    g, = read(worlds, world, prompt).groups
    assert (g.intent, g.via, g.destination) == ("walk", via, destination)


@pytest.mark.parametrize("world,prompt,intent", [
    ("mall", "Shoppers take the escalator.", "walk"),
    ("station", "Two commuters take the emergency stairs from platform 1.", "walk"),
    ("office", "Two interns take a break in the kitchen.", "wait"),
    ("hospital", "The cleaner uses the mop in the corridor.", "wait"),
])
def test_taking_a_way_is_walking_taking_a_thing_is_not(worlds, world, prompt, intent):
    g, = read(worlds, world, prompt).groups
    assert g.intent == intent


# ---- 7. a noun no list names that does something to itself is a person -------------------------------

@pytest.mark.parametrize("world,prompt,label,count,location", [
    ("mall", "Two hecklers position themselves by the fountain.", "heckler", 2, "fountain"),
    ("station", "A fiddler plants himself on the concourse.", "fiddler", 1, "concourse"),
    ("museum", "A prankster parks herself next to the whale skeleton.", "prankster", 1, "whale_skeleton"),
])
def test_a_noun_that_does_something_to_itself_is_a_person(worlds, world, prompt, label, count, location):
    g, = read(worlds, world, prompt).groups
    assert (g.label, g.count.value, g.location) == (label, count, location)


def test_a_thing_that_switches_itself_off_is_nobody(worlds):
    g, = read_prompt("The heater switches itself off in the kitchen.", worlds["residential"]).groups
    assert g.label == "person" and g.confidence_of("group") is not None


# ---- 8. the rest of a group that stays stays where the group is ---------------------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("hospital", "Two of the six nurses at the nurse station go to the pharmacy and the others stay.", "nurse_station"),
    ("residential", "Of the four kids in the living room, two go to the kitchen and the others stay.", "living_room"),
    ("office", "Of the eight developers in the open office, two head to the kitchen, while the rest keep working.",
     "open_plan_office"),
])
def test_the_rest_stay_where_their_group_is(worlds, world, prompt, location):
    g0, g1, g2 = read(worlds, world, prompt).groups
    assert (g2.relation, g2.intent, g2.location) == ("others_of:0", "wait", location)
    assert g1.relation == "subset_of:0" and g1.intent == "walk"
