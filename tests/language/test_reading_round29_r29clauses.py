"""Clause classes of round 29, each with sentences of its own over at least two worlds (none from the
understanding sets): a verb of going the small parser took for a plural noun after one person
("totters", "waddles", "trots") reacts to the robot it goes up to, and keeping pace with the robot is
following it; talk said by an idiom ("chinwag", "chew the fat"); someone who smokes is no fire, so
hurrying beside them is no evacuation."""

from __future__ import annotations

import pytest


# ---- 1. a manner verb of going up to the robot; keeping pace with it -----------------------------------

@pytest.mark.parametrize("world,prompt,interaction", [
    ("mall", "A little lass totters up to the robot, beaming.", "approach"),
    ("library", "A boy in the reading room totters towards the robot.", "approach"),
    ("library", "A student keeps pace with the robot, filming it.", "follow"),
    ("station", "Two kids keep pace with the robot across the concourse.", "follow"),
    ("stadium", "Two kids keep pace with the robot along the south concourse.", "follow"),
])
def test_a_manner_verb_up_to_the_robot_or_keeping_pace_reacts(read, world, prompt, interaction):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.robot_interaction, g.robot_reaction) == ("robot", interaction, "Curious")


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("mall", "A granny totters from the pharmacy to the fountain.", "pharmacy", "fountain"),
    ("hospital", "An old man waddles from the cafeteria to the pharmacy.", "cafeteria", "pharmacy"),
])
def test_a_manner_verb_without_the_robot_keeps_its_walk(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.start, g.destination) == ("walk", start, destination)


@pytest.mark.parametrize("world,prompt,interaction", [
    ("mall", "A small boy toddles over to the robot, delighted.", "approach"),
    ("mall", "An old chap waddles over to the robot, grinning.", "approach"),
    ("hospital", "An old lady totters over to the robot, smiling.", "approach"),
    ("stadium", "A toddler shies away from the robot, nervous.", "avoid"),
    ("airport", "Two kids trot after the robot, giggling.", "follow"),
])
def test_reactions_already_read_keep_their_reading(read, world, prompt, interaction):
    assert read(world, prompt).groups[0].robot_interaction == interaction


# ---- 2. talk said by an idiom -----------------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("library", "A pair of librarians chinwag in the staff room.", "staff_room"),
    ("hospital", "A couple of porters chinwag by the vending machine.", "vending_machine"),
    ("station", "Two guards are chinwagging on platform 2.", "platform_2"),
    ("airport", "Two cleaners gab by the toilets.", "toilets"),
    ("hotel", "A pair of waiters chew the rag by the bar.", "bar"),
    ("stadium", "While the robot patrols the south concourse, three stewards chinwag by the tea bar.", "tea_bar"),
])
def test_an_idiom_of_talk_is_conversing(read, world, prompt, location):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    assert (groups[0].intent, groups[0].location) == ("converse", location)


@pytest.mark.parametrize("world,prompt,intent", [
    ("library", "Two students natter in the cafe.", "converse"),
    ("station", "Two porters are chewing the fat by the ticket office.", "converse"),
    ("mall", "Three mums have a chinwag by the fountain.", "converse"),
    ("mall", "Four teenagers shoot the breeze by the fountain.", "converse"),
    ("mall", "A shopper chews gum by the fountain.", "wait"),
])
def test_talk_already_read_and_other_chewing_keep_their_reading(read, world, prompt, intent):
    assert read(world, prompt).groups[0].intent == intent


# ---- 3. someone smoking is no fire: hurrying is a walk -----------------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "Two nurses hurry from the staff room to the pharmacy, and a sous-chef smokes by the main entrance.",
     "staff_room", "pharmacy"),
    ("airport", "Two pilots hurry from the cafe to gate A1 while a baggage handler smokes by the east entrance.",
     "cafe", "gate_a1"),
    ("mall", "Three teens hurry from the cinema lobby to the food court while a shop assistant smokes by the west "
     "entrance.", "cinema_lobby", "food_court"),
    ("stadium", "Two fans hurry from the club shop to the concourse bar while a shop assistant smokes by gate A.",
     "club_shop", "concourse_bar"),
    ("station", "Two commuters hurry from the cafe to platform 1, and a sous-chef smokes beside the main entrance.",
     "cafe", "platform_1"),
])
def test_hurrying_beside_a_smoker_is_no_evacuation(read, world, prompt, start, destination):
    movers = [g for g in read(world, prompt).groups if g.destination is not None]
    assert [(g.intent, g.start, g.destination) for g in movers] == [("walk", start, destination)]


@pytest.mark.parametrize("world,prompt", [
    ("mall", "Smoke fills the food court and the shoppers hurry to the north exit."),
    ("station", "There is smoke on platform 2 and the travellers rush to the main entrance."),
])
def test_smoke_itself_still_makes_hurrying_an_evacuation(read, world, prompt):
    assert read(world, prompt).groups[0].intent == "evacuate"


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("station", "A porter smokes by the main entrance while two commuters hurry from the cafe to platform 1.",
     "cafe", "platform_1"),
    ("hotel", "A chef smokes by the service entrance while a pair of guests hurry from the bar to the lifts.",
     "bar", "lift_lobby"),
])
def test_hurrying_beside_a_smoker_already_read_keeps_its_reading(read, world, prompt, start, destination):
    movers = [g for g in read(world, prompt).groups if g.destination is not None]
    assert [(g.intent, g.start, g.destination) for g in movers] == [("walk", start, destination)]


# ---- 4. a part that gets up and does something at a place walks there -------------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("station", "Of the ten people in the waiting room, two get up and buy tickets at the ticket office.",
     "ticket_office"),
    ("mall", "Two shoppers get up and order at the coffee counter.", "coffee_counter"),
    ("hospital", "Of the eight in the main waiting room, three get up and pay at the pharmacy counter.",
     "pharmacy_counter"),
    ("dental_clinic", "Of the six people sat in the waiting room, one gets up and books in at reception.",
     "reception"),
])
def test_people_who_get_up_and_do_something_at_a_place_walk_there(read, world, prompt, destination):
    g = read(world, prompt).groups[-1]
    assert (g.intent, g.destination) == ("walk", destination)


@pytest.mark.parametrize("world,prompt,intent,location", [
    ("library", "Three students get up and queue at the issue desk.", "queue", "issue_desk"),
    ("mall", "Two shoppers stand up and wait by the fountain.", "wait", "fountain"),
    ("hospital", "Two visitors sit and read in the main waiting room.", "wait", "main_waiting_room"),
])
def test_getting_up_to_stay_or_queue_keeps_its_reading(read, world, prompt, intent, location):
    g = read(world, prompt).groups[-1]
    assert (g.intent, g.location) == (intent, location)
