"""Robot classes of round 37, each with sentences of its own over at least two worlds (none from the
understanding sets): the robot's round said as a habit ("keeps circling the lobby"); coming over to the
robot after seeing it ("spots the robot and hurries across"); following the robot said by "dog" or
"stalk"; a feeling about the robot said outright in a phrase ("in fright", "taken aback")."""

from __future__ import annotations

import pytest


# ---- 1. the robot's round said as a habit ----------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("hospital", "The robot keeps circling the waiting room while two nurses chat at the nurse station.",
     "main_waiting_room"),
    ("mall", "The robot keeps looping around the food court while a man waits by the fountain.", "food_court"),
    ("office", "The robot continues circling the open-plan floor.", "open_plan_office"),
    ("car_showroom", "The robot spends the afternoon circling the showroom floor.", "showroom"),
    ("library", "The robot keeps circling the reading room.", "reading_room"),
    ("zoo", "The robot keeps on prowling round the cafe while a keeper feeds the penguins.", "cafe"),
])
def test_the_robot_going_round_as_a_habit_patrols(read, world, prompt, location):
    r = read(world, prompt)
    assert r.robot is not None and (r.robot.task, r.robot.location) == ("patrol", location)


def test_the_robot_keeping_on_going_somewhere_still_crosses(read):
    r = read("hospital", "The robot keeps driving to the pharmacy.")
    assert r.robot is not None and (r.robot.task, r.robot.destination) == ("cross", "pharmacy")
    r = read("mall", "The robot goes round and round the food court.")
    assert r.robot is not None and (r.robot.task, r.robot.location) == ("patrol", "food_court")


@pytest.mark.parametrize("world,prompt,location", [
    ("museum", "The robot keeps waiting by the entrance.", "entrance_hall"),
    ("mall", "The robot continues waiting at the fountain while shoppers pass.", "fountain"),
    ("office", "The robot keeps standing by the reception desk.", "reception_desk"),
    ("hospital", "The robot keeps on waiting outside the pharmacy.", None),
])
def test_the_robot_staying_as_a_habit_waits(read, world, prompt, location):
    r = read(world, prompt)
    assert r.robot is not None and r.robot.task == "wait"
    assert location is None or r.robot.location == location


# ---- 2. coming over to the robot after seeing it ---------------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("hospital", "Two kids see the robot by the pharmacy and rush over, eager to see what it does."),
    ("mall", "A boy notices the robot near the fountain and runs over to have a look."),
    ("museum", "Two girls catch sight of the robot and dash across to get a closer look."),
    ("airport", "A teenager spots the robot and wanders over, keen to find out what it is."),
    ("zoo", "Three schoolkids spot the robot near the cafe and hurry across, desperate to meet it."),
])
def test_coming_over_after_seeing_the_robot_approaches_it(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.robot_interaction, g.robot_reaction) == ("robot", "approach", "Curious")


@pytest.mark.parametrize("world,prompt,destination", [
    ("museum", "A man stares at the robot and then walks over to the cafe.", "cafe"),
    ("mall", "A woman watches the robot and hurries across the food court.", None),
])
def test_looking_then_going_elsewhere_stays_a_look(read, world, prompt, destination):
    (g,) = read(world, prompt).groups
    assert (g.robot_interaction, g.robot_reaction) == ("look", "Surprised")


# ---- 3. following the robot said by "dog" or "stalk" -----------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("hospital", "A visitor dogs the robot through the waiting room."),
    ("mall", "Two boys dog the robot around the food court."),
    ("museum", "A curious child dogs the robot's every move in the main hall."),
    ("zoo", "Three schoolkids stalk the robot past the penguin pool."),
    ("office", "Two eager interns dog the robot's steps along the corridor."),
])
def test_dogging_or_stalking_the_robot_follows_it(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.robot_interaction, g.robot_reaction) == ("robot", "follow", "Curious")


def test_a_dog_near_the_robot_is_no_following(read):
    (g,) = read("hospital", "A woman with a dog stares at the robot.").groups
    assert g.robot_interaction == "look"
    (g,) = read("mall", "Two dog walkers wave at the robot.").groups
    assert g.robot_interaction == "look"
    (g,) = read("mall", "A man walks his dog past the robot.").groups
    assert g.robot_interaction != "follow"
    (g,) = read("residential", "The family dog-sitter stands in front of the robot in the kitchen.").groups
    assert g.robot_interaction == "block"


# ---- 4. a feeling about the robot said outright wins over the verb's own ---------------------------------

@pytest.mark.parametrize("world,prompt,interaction,reaction", [
    ("hospital", "A little boy stares at the robot and then bursts into tears in terror.", "look", "Scared"),
    ("mall", "Near the fountain a girl gawps at the robot, trembling with fear.", "look", "Scared"),
    ("museum", "A pensioner eyes the robot in alarm as it rolls past.", "look", "Scared"),
    ("station", "On platform 2 a small boy stares at the robot, then starts wailing in fright.", "look", "Scared"),
    ("zoo", "Taken aback by the robot, a keeper backs away from it.", "avoid", "Surprised"),
    ("office", "A temp steps aside in astonishment as the robot rolls by.", "avoid", "Surprised"),
    ("residential", "Taken aback at finding the robot in the kitchen, the grandmother edges away.", "avoid",
     "Surprised"),
])
def test_a_feeling_said_outright_gives_the_reaction(read, world, prompt, interaction, reaction):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.robot_interaction, g.robot_reaction) == ("robot", interaction, reaction)


@pytest.mark.parametrize("world,prompt,interaction,reaction", [
    ("airport", "A startled pensioner jumps back when the robot turns the corner.", "avoid", "Scared"),
    ("museum", "A little girl stares at the robot in amazement.", "look", "Surprised"),
    ("mall", "A frightened toddler backs away from the robot.", "avoid", "Scared"),
])
def test_a_feeling_that_agrees_with_the_verb_keeps_its_reading(read, world, prompt, interaction, reaction):
    (g,) = read(world, prompt).groups
    assert (g.robot_interaction, g.robot_reaction) == (interaction, reaction)
