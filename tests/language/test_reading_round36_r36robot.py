"""Robot-task classes of round 36, each with sentences of its own over at least two worlds (none from the
understanding sets): people who follow the robot said with a participle on the robot's own clause,
fronted or trailing ("Followed by a nurse, the robot drives to ..."); the robot's relative clause of
following ("a porter follows the robot which follows a doctor"); someone the robot picks up or meets at
a place and then escorts ("picks up a visitor at the entrance and escorts them to the cafe")."""

from __future__ import annotations

import pytest


# ---- 1. followers said with a participle on the robot's own clause ---------------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("hospital", "Followed by a nurse, the robot drives to the pharmacy.", "pharmacy"),
    ("mall", "Closely followed by two guards, the robot heads to the food court.", "food_court"),
    ("zoo", "Trailed by a keeper, the robot rolls over to the cafe.", "cafe"),
    ("hotel", "Followed by a porter, the robot goes to the lobby.", "lobby"),
    ("library", "Shadowed by a librarian, the robot drives to the issue desk.", "issue_desk"),
    ("hospital", "The robot drives to the pharmacy, followed by two porters.", "pharmacy"),
    ("mall", "The robot heads to the food court, trailed by three kids.", "food_court"),
    ("hotel", "The robot rolls to the lift lobby, followed closely by a porter.", "lift_lobby"),
    ("zoo", "The robot makes its way to the cafe, followed by a keeper.", "cafe"),
])
def test_people_said_following_the_robots_clause_follow_the_robot(read, world, prompt, destination):
    r = read(world, prompt)
    (g,) = r.groups
    assert (g.intent, g.robot_interaction, g.start) == ("robot", "follow", None)
    assert r.robot is not None and (r.robot.task, r.robot.destination) == ("cross", destination)


# ---- 2. the robot's relative clause of following ---------------------------------------------------------

@pytest.mark.parametrize("world,prompt,followed", [
    ("hospital", "A porter follows the robot which follows a doctor.", "a doctor"),
    ("mall", "A child follows the robot, which follows a guard.", "a guard"),
    ("zoo", "Two kids follow the robot that trails a zookeeper.", "a zookeeper"),
    ("hotel", "A porter trails the robot which follows the manager.", "the manager"),
    ("station", "A cleaner follows the robot, which in turn follows a guard.", "a guard"),
    ("airport", "A cleaner follows the robot, which follows a pilot.", "a pilot"),
])
def test_the_robot_of_a_relative_clause_follows_its_object(read, world, prompt, followed):
    r = read(world, prompt)
    assert r.robot is not None and (r.robot.task, r.robot.follows) == ("follow", followed)
    assert (r.groups[0].intent, r.groups[0].robot_interaction) == ("robot", "follow")
    assert [g.who for g in r.groups[1:]] == [followed]


# ---- 3. picked up or met at a place, then escorted -------------------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("museum", "The robot picks up a visitor at the entrance and escorts them to the cafe.", "entrance_hall", "cafe"),
    ("station", "The robot meets an elderly passenger at the ticket office and takes her to platform 2.",
     "ticket_office", "platform_2"),
    ("hotel", "The robot collects a guest from the lobby and brings him to the restaurant.", "lobby", "restaurant"),
    ("zoo", "The robot greets a family at the main gate and guides them to the cafe.", "main_gate", "cafe"),
    ("hospital", "The robot picks up a patient in radiology and takes him to the pharmacy.", "radiology", "pharmacy"),
])
def test_someone_picked_up_then_escorted_follows_the_robot_from_there(read, world, prompt, start, destination):
    r = read(world, prompt)
    (g,) = r.groups
    assert (g.robot_interaction, g.start, g.destination) == ("follow", start, destination)
    assert r.robot is not None and (r.robot.task, r.robot.start, r.robot.destination) == ("cross", start, destination)


# ---- guards: readings that stay as they were -------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,intent,destination", [
    ("mall", "Followed by her dad, a little girl runs to the food court.", "walk", "food_court"),
    ("hospital", "A nurse follows the robot, which drives to the pharmacy.", "robot", "pharmacy"),
    ("hospital", "The robot is followed by two porters through the main entrance.", "robot", "main_entrance"),
    ("museum", "A guard follows the robot into the cafe.", "robot", "cafe"),
])
def test_followers_of_people_and_plain_followers_of_the_robot_keep_their_reading(read, world, prompt, intent,
                                                                                   destination):
    g = read(world, prompt).groups[0]
    assert (g.intent, g.destination) == (intent, destination)


def test_a_person_followed_by_others_keeps_them_behind(read):
    groups = read("office", "The manager walks to the boardroom, followed by two assistants.").groups
    assert [(g.intent, g.destination) for g in groups] == [("walk", "boardroom"), ("follow", "boardroom")]


def test_a_thing_picked_up_makes_no_escort(read):
    r = read("office", "The robot picks up a parcel at reception and takes it to the kitchen.")
    assert r.robot is not None and (r.robot.task, r.robot.destination) == ("cross", "kitchen")
    assert all(g.robot_interaction != "follow" for g in r.groups)


# ---- 4. the owner of the robot's place stays in it -------------------------------------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("high_street_bank", "The robot ferries the post from Mr Shah's office to the cash office; he stays put in his.",
     "adviser_office_1"),
    ("gp_surgery", "The robot takes the samples from Dr Patel's room to reception while she stays in hers.",
     "consulting_room_1"),
    ("market_hall", "The robot carries the float from Mr Doyle's office to the cafe; he stays put in his.",
     "market_office"),
    ("town_hall", "The robot takes the minutes to Ms Adeyemi's office; she waits in hers.", "chief_executive_office"),
    ("care_home", "The robot wheels the laundry to Mr Reid's room, where he stays.", "room_4"),
])
def test_the_owner_of_the_robots_place_who_stays_is_there(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.location) == ("wait", location)


def test_an_owner_said_to_stay_nowhere_is_not_placed(read):
    (g,) = read("high_street_bank", "The robot takes the post from Mr Shah's office to the cash office.").groups
    assert g.location is None
