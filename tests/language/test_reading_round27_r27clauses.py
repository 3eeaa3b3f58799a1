"""Clause classes of round 27, each with sentences of its own over at least two worlds (none from the
understanding sets): a load pushed or pulled along a route is walking it; holding one's ground as the
robot comes is blocking it, keeping hold of the robot is following it; a fronted stay said by its place
("After 40 mins in the waiting hall, ..."); what an "until" clause waits for is no group and "till"
there is no shop's till."""

from __future__ import annotations

import pytest


# ---- 1. a load moved by hand along a route: walking it ----------------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("airport", "Two pilots pull their flight bags from the check-in hall to gate A1.", "check_in_hall", "gate_a1"),
    ("ferry_terminal", "Two backpackers pull their rucksacks from the check-in hall to the departure lounge.",
     "check_in_hall", "departure_lounge"),
    ("hotel", "Two guests pull their cases from the check-in desk to the lifts.", "reception_desk", "lift_lobby"),
    ("residential", "A lodger pulls his suitcase from the sitting room to the front door.", "living_room",
     "front_door"),
])
def test_a_load_moved_along_a_route_walks_it(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert g.intent == "walk"
    assert g.destination == destination
    if start is not None:
        assert g.start == start


@pytest.mark.parametrize("world,prompt,intent", [
    ("mall", "A cleaner drags a bin bag from the food court to the south entrance.", "walk"),
    ("hospital", "A porter tows a laundry cart from the main waiting room to the pharmacy.", "walk"),
    ("mall", "A child pulls the lever of a ride in the food court.", "wait"),
    ("hospital", "A nurse pushes a patient to the pharmacy.", "walk"),
])
def test_a_load_with_nowhere_said_or_a_person_pushed_keeps_its_reading(read, world, prompt, intent):
    groups = read(world, prompt).groups
    assert groups[0].intent == intent


# ---- 2. holding ground as the robot comes: blocking it ---------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("mall", "An angry shopper by the toy store stands her ground as the robot tries to pass."),
    ("station", "A drunk man on platform 1 holds his ground when the robot comes near."),
    ("hospital", "A stubborn visitor in the main waiting room stands his ground as the robot approaches."),
    ("consulate", "A furious man at counter 2 plants his feet as the robot tries to get by."),
])
def test_holding_ground_against_the_robot_blocks_it(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.robot_interaction, g.robot_reaction) == ("robot", "block", "Threatening")


# ---- 3. keeping hold of the robot: following it ----------------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("hospital", "An old man keeps a hand on the robot as it leads him from the main waiting room to the pharmacy."),
    ("museum", "A blind visitor holds on to the robot as it guides her through the great hall."),
    ("airport", "A nervous child clings to the robot as it takes her to gate A1."),
    ("care_home", "A frail resident keeps a hand on the robot as it guides her to the lounge."),
])
def test_keeping_hold_of_the_robot_follows_it(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.robot_interaction == "follow"


@pytest.mark.parametrize("world,prompt,interaction", [
    ("mall", "A girl stands in the food court as the robot passes.", None),
    ("hospital", "A nurse holds the door for a patient in the main waiting room.", None),
])
def test_standing_or_holding_with_no_idiom_keeps_its_reading(read, world, prompt, interaction):
    assert read(world, prompt).groups[0].robot_interaction == interaction


# ---- 4. a fronted stay said by where it was spent ---------------------------------------------------------

@pytest.mark.parametrize("world,prompt,seconds", [
    ("consulate", "After 20 mins in the waiting hall, an old man walks to counter 1.", 1200.0),
    ("hospital", "After an hour in the main waiting room, a patient goes to the pharmacy.", 3600.0),
    ("mall", "After ten minutes at the food court, two girls head to the toy store.", 600.0),
    ("station", "After half an hour in the cafe, a commuter walks to platform 2.", 1800.0),
])
def test_a_fronted_stay_at_a_place_is_a_wait_first(read, world, prompt, seconds):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.wait_seconds) == ("walk", seconds)


@pytest.mark.parametrize("world,prompt", [
    ("mall", "After ten minutes, two girls head to the toy store."),
    ("station", "After lunch in the cafe, a commuter walks to platform 2."),
])
def test_a_fronted_time_alone_is_no_stay(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.wait_seconds is None


# ---- 5. what an "until" clause waits for is no group, and its "till" no place ----------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("hotel", "Four guests wait in the lobby until the airport coach arrives.", "lobby"),
    ("bus_station", "Two students sit in the cafe until the Glasgow coach comes.", "cafe"),
    ("ferry_terminal", "A couple waits in the departure lounge until the coach pulls in.", "departure_lounge"),
    ("stadium", "Ten fans hang around the concourse till the team coach leaves.", None),
])
def test_what_an_until_clause_waits_for_is_no_group(read, world, prompt, place):
    (g,) = read(world, prompt).groups
    assert g.intent == "wait"
    assert g.location != "shop_till"
    if place is not None:
        assert g.location == place


@pytest.mark.parametrize("world,prompt,place", [
    ("supermarket", "Two shoppers queue at the till.", "checkouts"),
    ("stadium", "A fan queues at the shop till.", "shop_till"),
])
def test_a_till_that_is_a_place_stays_one(read, world, prompt, place):
    (g,) = read(world, prompt).groups
    assert g.location == place


def test_a_person_waited_for_is_still_read(read):
    groups = read("hospital", "A patient waits in the main waiting room until a nurse comes, and a porter mops "
                              "the pharmacy.").groups
    assert len(groups) >= 2


# ---- 6. the robot bringing something to someone where they are: they wait there ---------------------------

@pytest.mark.parametrize("world,prompt,who,place,robot_from", [
    ("care_home", "The robot takes Mr Jones his tea from the kitchen to the lounge, where he is dozing.", "Mr Jones",
     "lounge", "kitchen"),
    ("hospital", "The robot carries a patient's medication from the pharmacy to the main waiting room, where she "
                 "is waiting.", "a patient", "main_waiting_room", "pharmacy"),
    ("residential", "The robot brings Grandad his slippers from the bedroom to the sofa where he's dozing.",
     "Grandad", "sofa", "master_bedroom"),
    ("care_home", "The robot brings Auntie Pat's cardigan from the kitchen to the lounge where she's knitting.",
     "Auntie Pat", "lounge", "kitchen"),
])
def test_someone_the_robot_brings_a_thing_to_waits_where_it_goes(read, world, prompt, who, place, robot_from):
    reading = read(world, prompt)
    (g,) = reading.groups
    assert (g.who, g.count.value, g.intent, g.location, g.robot_interaction) == (who, 1, "wait", place, None)
    assert reading.robot is not None
    assert (reading.robot.task, reading.robot.start, reading.robot.destination) == ("cross", robot_from, place)


@pytest.mark.parametrize("world,prompt,who,interaction", [
    ("hospital", "The robot takes a patient from the main waiting room to the pharmacy.", "a patient", "follow"),
    ("care_home", "The robot brings Mr Jones to the lounge.", "Mr Jones", "follow"),
])
def test_someone_the_robot_brings_along_still_follows_it(read, world, prompt, who, interaction):
    (g,) = read(world, prompt).groups
    assert (g.who, g.robot_interaction) == (who, interaction)
