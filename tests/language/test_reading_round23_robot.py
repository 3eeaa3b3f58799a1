"""Robot classes of round 23, each with sentences of its own over at least two worlds (none from the
understanding sets): the robot through, past or around a crowd, a queue or a group (the people stay
where they are, a group there, and their place is one the robot passes); the robot staying or going
round said in other words; people who let the robot lead them; a reaction said as a state."""

from __future__ import annotations

import pytest


# ---- 1. the robot through, past or around people ----------------------------------------------------

@pytest.mark.parametrize("world,prompt,kind,intent,location,destination", [
    ("station", "The robot picks its way through the crowd of commuters on the concourse to reach platform 2.",
     "vague", "wait", "concourse", "platform_2"),
    ("airport", "The robot edges its way past the queue of passengers at the security checkpoint towards gate B1.",
     "implied", "queue", "security_checkpoint", "gate_b1"),
    ("mall", "The robot noses its way through a throng of shoppers in the food court to get to the cinema lobby.",
     "vague", "wait", "food_court", "cinema_lobby"),
    ("museum", "The robot squeezes past a group of pupils in the great hall on its way to the cafe.",
     "implied", "wait", "great_hall", "cafe"),
])
def test_people_the_robot_makes_its_way_through_are_a_group_where_they_are(read, world, prompt, kind, intent,
                                                                            location, destination):
    r = read(world, prompt)
    (g,) = r.groups
    assert (g.count.kind, g.intent, g.location, g.destination, g.robot_interaction) == (kind, intent, location, None,
                                                                                        None)
    assert r.robot is not None and (r.robot.task, r.robot.destination, r.robot.via) == ("cross", destination,
                                                                                      (location,))


@pytest.mark.parametrize("world,prompt,location,destination", [
    ("station", "Thirty commuters queue at the ticket office while the robot rolls past the queue to the cafe.",
     "ticket_office", "cafe"),
    ("airport", "A dozen passengers wait at gate A2 as the robot weaves around them towards the duty free.",
     "gate_a2", "duty_free"),
    ("mall", "Forty shoppers crowd the food court as the robot picks its way through them to the cinema lobby.",
     "food_court", "cinema_lobby"),
    ("museum", "Twenty pupils crowd around the whale skeleton while the robot edges past them to the cafe.",
     "whale_skeleton", "cafe"),
    ("museum", "A crowd of tourists fills the entrance hall and the robot threads a path through them to the gift shop.",
     "entrance_hall", "gift_shop"),
])
def test_the_place_of_people_said_before_is_where_the_robot_passes(read, world, prompt, location, destination):
    r = read(world, prompt)
    (g,) = r.groups
    assert g.location == location and g.robot_interaction is None
    assert r.robot is not None and (r.robot.task, r.robot.destination, r.robot.via) == ("cross", destination,
                                                                                      (location,))


def test_gathering_round_the_robot_itself_is_still_coming_to_it(read):
    (g,) = read("mall", "Twenty kids crowd round the robot at the fountain.").groups
    assert g.robot_interaction == "approach"
    (g,) = read("station", "Two porters chat to the robot on platform 1.").groups
    assert g.robot_interaction == "approach"


# ---- 2. the robot staying or going round said in other words -----------------------------------------

@pytest.mark.parametrize("world,prompt,task,location", [
    ("station", "Have the robot park by the ticket machines while two porters natter in the staff office.",
     "wait", "ticket_machines"),
    ("hotel", "Have the robot park beside the concierge desk while a porter naps in the luggage room.",
     "wait", "concierge_desk"),
    ("mall", "A dozen shoppers browse the bookshop as the robot goes up and down the west mall.", "patrol", "west_mall"),
    ("market_hall", "Two traders chat by the butcher's as the robot trundles back and forth along the middle aisle.",
     "patrol", "central_aisle"),
    ("station", "The robot rolls to and fro along platform 1 while a guard waits by the gateline.", "patrol",
     "platform_1"),
])
def test_parking_or_going_to_and_fro_is_a_wait_or_a_patrol(read, world, prompt, task, location):
    robot = read(world, prompt).robot
    assert robot is not None and (robot.task, robot.location, robot.via) == (task, location, ())


# ---- 3. people who let the robot lead them to a room by its number ------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hotel", "Jet-lagged after a long flight, a guest lets the robot take him from the lobby to number 104.",
     "lobby", "room_104"),
    ("hotel", "A confused old man lets the robot guide him from the bar to no. 109.", "bar", "room_109"),
    ("hotel", "Back from the spa, a woman lets the robot walk her from the lift lobby to #102.", "lift_lobby",
     "room_102"),
    ("hotel", "A tipsy wedding guest lets the robot lead him from the ballroom to Number 110.", "ballroom",
     "room_110"),
])
def test_a_room_said_by_number_is_where_the_robot_leads_them(read, world, prompt, start, destination):
    r = read(world, prompt)
    (g,) = r.groups
    assert g.robot_interaction == "follow" and r.unknown_places == ()
    assert r.robot is not None and (r.robot.task, r.robot.start, r.robot.destination) == ("cross", start, destination)


# ---- 4. a reaction said as a state ------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("office", "Busy on a call at her desk, the receptionist pays the robot no attention.", None),
    ("mall", "Engrossed in a phone call by the fountain, a teenager pays the robot no heed at all.", "fountain"),
    ("station", "Stuck in a long video call on platform 2, a commuter ignores the robot.", "platform_2"),
])
def test_a_call_someone_is_on_is_no_place(read, world, prompt, location):
    r = read(world, prompt)
    (g,) = r.groups
    assert r.unknown_places == () and g.robot_interaction is None
    assert location is None or g.location == location


@pytest.mark.parametrize("world,prompt,location", [
    ("hospital", "A new cleaner by the lifts is frightened of the robot and cowers whenever it trundles by.",
     "elevator_hall"),
    ("parcel_depot", "A temp driver at van bay B is frightened of the robot and cowers whenever it rolls by.",
     "van_bay_b"),
    ("museum", "A shy pupil in the cafe is frightened of the robot and cowers whenever it trundles past.", "cafe"),
])
def test_a_second_verb_of_one_person_is_no_group(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert (g.count.value, g.robot_interaction, g.robot_reaction, g.location) == (1, "avoid", "Scared", location)
