"""Robot classes of round 43, each with sentences of its own over at least two worlds (none from the
understanding sets):

1. a threatening gesture made at the robot ("shakes his fist at the robot", "jabs a finger at it",
   "brandishes a walking stick at it", "makes a rude gesture at it") is hostile: block, Threatening, not a
   look as other things done "at" it (language/hostile_gestures.py);
2. the robot said with its owner ("our robot", "my robot", "the store's robot") is the subject of its own
   clause, and its verb is its task (language/robot_owners.py)."""

from __future__ import annotations

import pytest


# ---- 1. a threatening gesture at the robot ---------------------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("mall", "An angry shopper shakes his fist at the robot."),
    ("mall", "By the fountain, a bored teenager jabs a finger at the robot."),
    ("hospital", "A drunk patient wags a finger at the robot in the entrance lobby."),
    ("office", "A furious manager waves his umbrella at the robot."),
    ("station", "A commuter makes a rude gesture at the robot as it passes the ticket office."),
    ("station", "An old man brandishes a walking stick at the robot."),
    ("museum", "A grumpy guard sticks two fingers up at the robot."),
    ("library", "A student who failed her exam shakes her fists at the robot by the issue desk."),
])
def test_a_threatening_gesture_at_the_robot_is_hostile(read, world, prompt):
    group = read(world, prompt).groups[0]
    assert group.intent == "robot"
    assert group.robot_interaction == "block"
    assert group.robot_reaction == "Threatening"


# ---- guards: friendly things done at the robot stay a look -------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("mall", "A kid waves at the robot."),
    ("mall", "A kid waves a flag at the robot."),
    ("museum", "A little girl points a finger at the robot."),
    ("hospital", "Two children wave their hands at the robot."),
    ("station", "A tourist points at the robot and laughs."),
])
def test_friendly_gestures_at_the_robot_stay_a_look(read, world, prompt):
    group = read(world, prompt).groups[0]
    assert group.robot_interaction == "look"


@pytest.mark.parametrize("world,prompt", [
    ("office", "An angry client hurls abuse at the robot."),
    ("mall", "A drunk throws a cup at the robot."),
])
def test_hostile_verbs_at_the_robot_keep_their_reading(read, world, prompt):
    group = read(world, prompt).groups[0]
    assert group.robot_interaction == "block"


# ---- 2. the robot said with its owner -------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,task,location", [
    ("mall", "Two guards chat by the fountain while our robot patrols the west mall.", "patrol", "west_mall"),
    ("mall", "Two guards chat by the fountain while my robot waits at the pharmacy.", "wait", "pharmacy"),
    ("mall", "Two guards chat by the fountain while the store's robot waits at the pharmacy.", "wait", "pharmacy"),
    ("ice_rink", "Two coaches chat in the cafe while our robot does laps of the concourse.", "patrol", "concourse"),
    ("office", "Two staff chat in the kitchen while their robot does circuits of the open plan office.",
     "patrol", "open_plan_office"),
    ("library", "A student naps in the reading room as our robot waits by the issue desk.", "wait", "issue_desk"),
])
def test_the_robot_with_its_owner_has_its_task(read, world, prompt, task, location):
    r = read(world, prompt)
    assert r.robot is not None and r.robot.task == task
    assert r.robot.location == location
    assert len(r.groups) == 1


def test_the_hospitals_robot_crossing_has_its_route(read):
    r = read("hospital", "Two nurses chat at the reception desk as the hospital's delivery robot carries blankets "
                         "from the pharmacy to the main waiting room.")
    assert r.robot is not None and r.robot.task == "cross"
    assert (r.robot.start, r.robot.destination) == ("pharmacy", "main_waiting_room")


# ---- guards: the robot said plainly, and people's robots they react to, keep their reading -----------------

@pytest.mark.parametrize("world,prompt,task", [
    ("mall", "Two guards chat by the fountain while the robot patrols the west mall.", "patrol"),
    ("office", "Our robot patrols the main corridor while two staff chat in the kitchen.", "patrol"),
    ("mall", "Two kids trot after our robot round the food court.", None),
])
def test_plain_robots_and_robots_people_react_to_keep_their_reading(read, world, prompt, task):
    r = read(world, prompt)
    assert (r.robot.task if r.robot is not None else None) == task


# ---- 3. the robot said again as "the machine" -------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,interaction", [
    ("mall", "When the robot rolls in, a toddler stares at the machine.", "look"),
    ("mall", "The robot crosses the main atrium and an old man backs away from the contraption.", "avoid"),
    ("station", "A commuter who dislikes robots steers clear of the machine by the ticket office.", "avoid"),
    ("hospital", "The robot rolls into the entrance lobby and a nervous visitor edges away from the machine.",
     "avoid"),
    ("museum", "The robot glides into the great hall and two kids run after that gadget.", "follow"),
])
def test_the_machine_said_after_the_robot_is_the_robot(read, world, prompt, interaction):
    group = read(world, prompt).groups[0]
    assert group.intent == "robot"
    assert group.robot_interaction == interaction


# ---- guards: a machine the world has, or a machine with no robot said, keeps its reading --------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("mall", "The robot crosses the main atrium and an old man walks to the cash machine.", "cash_machine"),
    ("office", "Two staff walk to the coffee machine while the robot waits at reception.", "coffee_machine"),
])
def test_named_machines_stay_places(read, world, prompt, destination):
    group = read(world, prompt).groups[0]
    assert group.destination == destination
    assert group.intent == "walk"


def test_a_machine_with_no_robot_said_is_no_robot(read):
    group = read("mall", "A toddler stares at the machine.").groups[0]
    assert group.intent != "robot"
