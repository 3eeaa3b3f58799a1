"""Clause classes of round 31, each with sentences of its own over at least two worlds (none from the
understanding sets): going away from the robot by any verb; a purpose that names where people go;
going to where a problem is; a place the world lacks, searched for by its kind."""

from __future__ import annotations

import pytest


# ---- 1. going away from the robot by any verb -----------------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("airport", "A toddler at gate A1 scurries away from the robot."),
    ("mall", "A little boy by the fountain skitters back from the robot."),
    ("hospital", "A frail patient in the cafeteria cringes away from the robot."),
    ("library", "A student at the issue desk slinks off away from the robot."),
    ("zoo", "A small girl by the gift shop scampers away from the robot."),
])
def test_going_away_from_the_robot_by_any_verb_avoids_it(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert (g.robot_interaction, g.robot_reaction) == ("avoid", "Scared")


def test_going_away_from_a_place_is_no_reaction(read):
    (g,) = read("mall", "A boy walks away from the fountain.").groups
    assert (g.robot_interaction, g.start) == (None, "fountain")


# ---- 2. a purpose that names where people go ------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("airport", "Two pilots leave the lounge, late for boarding at gate A1.", "airline_lounge", "gate_a1"),
    ("airport", "A family hurries out of duty free, in time for boarding at gate B1.", "duty_free", "gate_b1"),
    ("hospital", "A nurse hurries out of the cafeteria, late for her shift in the pharmacy.", "cafeteria", "pharmacy"),
    ("station", "A student dashes out of the newsagent, late for the 8:40 on platform 1.", "newsagent", "platform_1"),
])
def test_a_purpose_at_a_place_names_the_destination(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.start, g.destination) == ("walk", start, destination)


def test_a_destination_said_keeps_its_place(read):
    (g,) = read("airport", "Two pilots leave the lounge and head for gate A1.").groups
    assert (g.start, g.destination) == ("airline_lounge", "gate_a1")
    (g,) = read("station", "A commuter hurries out of the waiting room, off to catch the 9:15 from platform 1.").groups
    assert (g.start, g.destination) == ("waiting_room", "platform_1")


# ---- 3. going to where a problem is ---------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("mall", "There's a spill in the food court, so a cleaner comes over from the pharmacy to deal with it.",
     "pharmacy", "food_court"),
    ("hospital", "A fight breaks out in the cafeteria, and two porters run over from the pharmacy to break it up.",
     "pharmacy", "cafeteria"),
    ("station", "There's a row at the ticket office, so a guard hurries over from platform 1 to sort things out.",
     "platform_1", "ticket_office"),
    ("library", "There's a mix-up at the issue desk, so a librarian comes down from the cafe to sort it out.",
     "cafe", "issue_desk"),
])
def test_going_to_see_to_a_problem_goes_where_it_is(read, world, prompt, start, destination):
    groups = read(world, prompt).groups
    g = groups[-1]
    assert (g.intent, g.start, g.destination) == ("walk", start, destination)


# ---- 4. a place the world lacks, searched for by its kind ----------------------------------------------------

@pytest.mark.parametrize("world,prompt,unknown", [
    ("mall", "Two teens wander off from the fountain looking for a pub.", "pub"),
    ("station", "A visitor leaves the cafe in search of a cashpoint.", "cashpoint"),
    ("hospital", "Two visitors leave the cafeteria hunting for a cashpoint.", "cashpoint"),
    ("ice_rink", "A dad wanders off from the cafe looking for a pub.", "pub"),
])
def test_a_kind_of_place_searched_for_that_the_world_lacks_is_refused(read, world, prompt, unknown):
    assert unknown in read(world, prompt).unknown_places


def test_searching_for_a_thing_or_a_place_the_world_has_refuses_nothing(read):
    assert read("hospital", "A porter leaves the cafeteria looking for a spare trolley.").unknown_places == ()
    assert read("mall", "Two teens wander off from the fountain looking for a cashpoint.").unknown_places == ()


# ---- 5. a place said by what is done there is the room, not a thing in it ----------------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("planetarium", "Three pupils walk from the foyer to the place where they spin the star ball.", "dome_theatre"),
    ("planetarium", "Four pupils wander from the gift shop to the place where they spin the star machine.",
     "dome_theatre"),
    ("airport", "A couple walk from the cafe to the place where they scan your bags.", "security_checkpoint"),
    ("airport", "Two kids run from the cafe to the place where the suitcases come round on the carousel.",
     "baggage_claim"),
    ("hospital", "A porter walks from the lobby to the place where they take the X-rays.", "radiology"),
])
def test_a_place_said_by_what_is_done_there_is_the_room(read, world, prompt, destination):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.destination) == ("walk", destination)


def test_a_fixture_people_use_stays_the_fixture(read):
    (g,) = read("mall", "A dad walks from the fountain to the place where you get cash out.").groups
    assert g.destination == "cash_machine"
    (g,) = read("station", "A tourist walks from the cafe to the place where you buy tickets from a machine.").groups
    assert g.destination == "ticket_machines"
    (g,) = read("mall", "Two girls stroll from the fountain to the place where they make the coffee.").groups
    assert g.destination == "coffee_counter"
