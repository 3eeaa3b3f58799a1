"""Robot classes of round 25, each with sentences of its own over at least two worlds (none from the
understanding sets): a reaction said as a feeling of state ("petrified of the robot", "mesmerised by
it"); a way of moving in the robot's wake or at its heels, and keeping an eye on it; the robot staying
put said by its state ("bot idle nr pulpit") or by whoever places it ("park the robot by ..."); the
robot's destination said first as its purpose ("To reach the toy store, the robot must ..."); the robot
showing people to a place; lengths ("within a few metres") that are nobody."""

from __future__ import annotations

import pytest


# ---- 1. a feeling of state about the robot -----------------------------------------------------------

@pytest.mark.parametrize("world,prompt,interaction,reaction,location", [
    ("museum", "A small boy near the whale skeleton is petrified of the robot.", "avoid", "Scared", "whale_skeleton"),
    ("library", "A girl by the issue desk is unnerved by the robot.", "avoid", "Scared", "issue_desk"),
    ("zoo", "A toddler by the penguin beach is intrigued by the robot.", "approach", "Curious", "penguin_beach"),
    ("airport", "A pilot at gate A1 is mesmerised by the robot.", "approach", "Curious", "gate_a1"),
    ("station", "A porter on platform 1 is furious with the robot.", "block", "Threatening", "platform_1"),
])
def test_a_feeling_of_state_about_the_robot_is_a_reaction(read, world, prompt, interaction, reaction, location):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.robot_interaction, g.robot_reaction, g.location) == ("robot", interaction, reaction,
                                                                             location)


def test_a_terrified_person_who_goes_off_avoids_the_robot(read):
    (g,) = read("hospital", "An old man at reception is terrified of the robot and shuffles off.").groups
    assert (g.intent, g.robot_interaction, g.robot_reaction) == ("robot", "avoid", "Scared")


# ---- 2. in the robot's wake, at its heels; an eye kept on it -----------------------------------------

@pytest.mark.parametrize("world,prompt,via", [
    ("mall", "Two teens tiptoe in the robot's wake past the fountain.", ("fountain",)),
    ("hospital", "A little boy scampers along in the robot's wake down the main corridor.", ("main_corridor",)),
    ("cathedral", "Three choristers pad along at the robot's heels through the nave.", ("nave",)),
    ("library", "Two kids creep along on the robot's tail through the reading room.", ("reading_room",)),
])
def test_moving_in_the_robots_wake_follows_it(read, world, prompt, via):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.robot_interaction, g.robot_reaction, g.via) == ("robot", "follow", "Curious", via)


@pytest.mark.parametrize("world,prompt,location", [
    ("museum", "A guard keeps an eye on the robot in the great hall.", "great_hall"),
    ("stadium", "Two stewards keep an eye on the robot at the main gate.", "gate_a"),
    ("hospital", "A porter keeps tabs on the robot in the waiting room.", "main_waiting_room"),
    ("mall", "A security guard keeps tabs on the robot by the fountain.", "fountain"),
    ("airport", "Two pilots at gate A1 keep tabs on the robot.", "gate_a1"),
])
def test_keeping_an_eye_on_the_robot_is_looking_at_it(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert (g.robot_interaction, g.robot_reaction, g.location) == ("look", "Surprised", location)


# ---- 3. the robot staying put, by its state or by who places it --------------------------------------

@pytest.mark.parametrize("world,prompt,location,group_location", [
    ("office", "bot idle by reception, 2 devs in boardroom", "reception", "boardroom"),
    ("cathedral", "3 tourists in the nave, robot stationary by the font", "font", "nave"),
    ("hospital", "robot on standby at the nurse station, 2 nurses in the pharmacy", "nurse_station", "pharmacy"),
    ("library", "Two students read in the reading room while the robot is motionless by the issue desk.",
     "issue_desk", "reading_room"),
])
def test_the_robot_in_a_state_of_staying_waits_there(read, world, prompt, location, group_location):
    r = read(world, prompt)
    (g,) = r.groups
    assert g.location == group_location
    assert r.robot is not None and (r.robot.task, r.robot.location, r.robot.via) == ("wait", location, ())


@pytest.mark.parametrize("world,prompt,location", [
    ("residential", "Park the robot by the back door while Dad cooks in the kitchen.", "back_door"),
    ("hospital", "Two nurses chat at the nurse station; station the robot by the lifts.", "elevator_hall"),
    ("museum", "Leave the robot in the great hall and have ten pupils wander the dinosaur gallery.", "great_hall"),
    ("supermarket", "A cashier waits at the tills and park the robot by the trolley bay.", "trolley_bay"),
])
def test_placing_the_robot_somewhere_is_its_wait_there(read, world, prompt, location):
    r = read(world, prompt)
    assert len(r.groups) == 1 and r.groups[0].robot_interaction is None
    assert r.robot is not None and (r.robot.task, r.robot.location) == ("wait", location)


# ---- 4. the robot's destination said first as its purpose --------------------------------------------

@pytest.mark.parametrize("world,prompt,destination,location", [
    ("mall", "To reach the cinema lobby, the robot must weave past twenty shoppers at the fountain.", "cinema_lobby",
     "fountain"),
    ("airport", "To get to gate B1, the robot squeezes past a dozen passengers queuing at the cafe.", "gate_b1", "cafe"),
    ("hospital", "In order to reach the pharmacy, the robot threads its way through the crowd in the waiting room.",
     "pharmacy", "main_waiting_room"),
    ("library", "To get to the issue desk, the robot has to edge past a group of students in the reading room.",
     "issue_desk", "reading_room"),
])
def test_a_fronted_purpose_is_where_the_robot_goes(read, world, prompt, destination, location):
    r = read(world, prompt)
    (g,) = r.groups
    assert (g.location, g.destination, g.robot_interaction) == (location, None, None)
    assert r.robot is not None and (r.robot.task, r.robot.destination, r.robot.via) == ("cross", destination,
                                                                                      (location,))
    assert r.robot.passes == (g.who,)


@pytest.mark.parametrize("world,prompt,destination,location", [
    ("hospital", "On its way to the pharmacy, the robot passes two nurses chatting at the nurse station.", "pharmacy",
     "nurse_station"),
    ("airport", "Heading for gate B1, the robot weaves past a dozen passengers queuing at the cafe.", "gate_b1", "cafe"),
    ("mall", "On the way to the cinema lobby, the robot threads through twenty shoppers at the fountain.",
     "cinema_lobby", "fountain"),
    ("museum", "Bound for the cafe, the robot edges past a group of pupils in the great hall.", "cafe", "great_hall"),
    ("station", "Making for platform 2, the robot squeezes through the crowd on the concourse.", "platform_2",
     "concourse"),
])
def test_a_fronted_way_is_where_the_robot_goes_not_the_peoples(read, world, prompt, destination, location):
    r = read(world, prompt)
    (g,) = r.groups
    assert (g.location, g.destination) == (location, None)
    assert r.robot is not None and (r.robot.task, r.robot.destination, r.robot.via) == ("cross", destination,
                                                                                      (location,))


def test_a_persons_fronted_way_stays_theirs(read):
    r = read("hospital", "On her way to the pharmacy, a nurse passes the robot.")
    (g,) = r.groups
    assert g.destination == "pharmacy" and r.robot is None


# ---- 5. the robot showing people to a place ---------------------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("station", "the robot shows 3 tourists from the ticket office to platform 2", "ticket_office", "platform_2"),
    ("hospital", "The robot shows an elderly patient to the pharmacy.", None, "pharmacy"),
    ("mall", "The robot shows two lost children the way to the information desk.", None, "information_desk"),
    ("museum", "The robot shows a school party from the entrance hall to the cafe.", "entrance_hall", "cafe"),
])
def test_showing_people_to_a_place_leads_them_there(read, world, prompt, start, destination):
    r = read(world, prompt)
    (g,) = r.groups
    assert (g.robot_interaction, g.destination) == ("follow", destination)
    assert r.robot is not None and (r.robot.task, r.robot.start, r.robot.destination, r.robot.guides) == (
        "cross", start, destination, g.who)


# ---- 6. a length is nobody ------------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,interaction", [
    ("hospital", "A toddler hides behind his mum whenever the robot comes within a few metres.", "avoid"),
    ("mall", "Whenever the robot gets within two metres of them, the kids at the fountain run over.", "approach"),
    ("library", "A student at the issue desk backs away whenever the robot comes within three feet.", "avoid"),
    ("airport", "Whenever the robot rolls within a few yards of gate A1, two children wave at it.", "look"),
])
def test_a_length_near_the_robot_is_no_group(read, world, prompt, interaction):
    (g,) = read(world, prompt).groups
    assert g.robot_interaction == interaction


# ---- guards: readings that must stay ----------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination,task,location", [
    ("hospital", "While the robot does laps of the ward, a nurse walks from the pharmacy to reception.", "pharmacy",
     "reception_desk", "patrol", "ward_a"),
    ("museum", "A guard strolls from the entrance hall to the cafe and the robot does its rounds.", "entrance_hall",
     "cafe", "patrol", None),
    ("station", "To catch the train, two commuters hurry to platform 2 while the robot waits by the cafe.", None,
     "platform_2", "wait", "cafe"),
    ("airport", "A cleaner leaves her trolley at gate A1 and the robot parks at the cafe.", "gate_a1", None, "wait",
     "cafe"),
])
def test_the_robots_rounds_or_stay_leave_the_peoples_clause_alone(read, world, prompt, start, destination, task,
                                                                    location):
    r = read(world, prompt)
    (g,) = r.groups
    assert (g.start, g.destination, g.robot_interaction) == (start, destination, None)
    assert r.robot is not None and (r.robot.task, r.robot.location) == (task, location)


@pytest.mark.parametrize("world,prompt,interaction", [
    ("mall", "A gang of teens refuse to let the robot past at the fountain.", "block"),
    ("station", "Three lads won't let the robot by on the concourse.", "block"),
    ("station", "Two tourists keep the robot in sight as it crosses the concourse.", "look"),
    ("hospital", "A nurse steps aside whenever the robot comes near.", "avoid"),
])
def test_blocking_watching_and_making_way_stay(read, world, prompt, interaction):
    (g,) = read(world, prompt).groups
    assert g.robot_interaction == interaction


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("airport", "The robot escorts two passengers from check-in to gate B1.", "check_in_hall", "gate_b1"),
    ("hospital", "The robot leads a patient from reception to the pharmacy.", "reception_desk", "pharmacy"),
])
def test_the_robot_leading_people_keeps_its_route(read, world, prompt, start, destination):
    r = read(world, prompt)
    assert r.robot is not None and (r.robot.task, r.robot.start, r.robot.destination) == ("cross", start, destination)


def test_excited_people_going_elsewhere_do_not_react(read):
    (g,) = read("mall", "Excited children run to the toy store while the robot waits by the fountain.").groups
    assert (g.robot_interaction, g.destination) == (None, "toy_store")
