"""Round 20 of the reader's clauses and reactions: a reaction said by a situation (standing where the
robot is heading is blocking it; gaping at it in astonishment is looking; not giving it a second
glance is no reaction at all), an aside between the robot and its verb ("the robot, meanwhile,
keeps patrolling"), and talk said by a verb of arguing."""

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("office", "A security guard plants himself right where the robot is heading, deliberately."),
    ("office", "An irritated courier stands right where the robot is going in the main corridor."),
    ("mall", "A teenager deliberately parks himself exactly where the robot is heading by the fountain."),
    ("hospital", "An angry visitor stations herself where the robot is rolling, on purpose."),
])
def test_standing_where_the_robot_is_heading_blocks_it(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.robot_interaction == "block" and g.robot_reaction == "Threatening"


@pytest.mark.parametrize("world,prompt", [
    ("office", "A visitor gapes in astonishment as the robot glides past the reception desk."),
    ("mall", "A child gawps in amazement as the robot trundles past the food court."),
    ("mall", "An old man stands by the fountain in disbelief as the robot sweeps by."),
    ("hospital", "A patient gapes as the robot glides along the main corridor."),
])
def test_gaping_in_astonishment_as_the_robot_passes_is_looking(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.robot_interaction == "look" and g.robot_reaction == "Surprised"


@pytest.mark.parametrize("world,prompt,intent", [
    ("office", "A courier walks to the kitchen, not giving the robot a second glance.", "walk"),
    ("office", "A manager walks to the boardroom without so much as a glance at the robot.", "walk"),
    ("mall", "A shopper heads for the food court, not giving the robot a second look.", "walk"),
    ("mall", "Two teenagers walk to the fountain without a single glance at the robot.", "walk"),
])
def test_no_second_glance_at_the_robot_is_no_reaction(read, world, prompt, intent):
    (g,) = read(world, prompt).groups
    assert g.intent == intent and g.robot_interaction is None and g.robot_reaction is None


@pytest.mark.parametrize("world,prompt,intent", [
    ("office", "Two interns chat in the kitchen; the robot, meanwhile, keeps patrolling.", "converse"),
    ("office", "Two interns chat in the kitchen, and the robot, for its part, patrols the main corridor.", "converse"),
    ("hospital", "A porter nods off in the staff room while the robot, meanwhile, keeps patrolling.", "wait"),
    ("hospital", "A nurse dozes off in the staff room, and the robot, meanwhile, keeps patrolling the main "
                 "corridor.", "wait"),
])
def test_an_aside_between_the_robot_and_its_verb(read, world, prompt, intent):
    r = read(world, prompt)
    (g,) = r.groups
    assert g.intent == intent
    assert r.robot is not None and r.robot.task == "patrol"


@pytest.mark.parametrize("world,prompt,location", [
    ("office", "Two colleagues bicker by the coffee machine.", "coffee_machine"),
    ("office", "Three interns squabble in the kitchen.", "kitchen"),
    ("office", "Two managers have words in the boardroom.", "boardroom"),
    ("mall", "A couple quarrel by the fountain.", "fountain"),
    ("hospital", "Two relatives bicker in the waiting room.", "main_waiting_room"),
])
def test_arguing_is_talk(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert g.intent == "converse" and g.location == location


@pytest.mark.parametrize("world,prompt,destination", [
    ("hotel", "A guest wanders from the lobby up to 103.", "room_103"),
    ("hotel", "A porter heads back to 104 with the luggage.", "room_104"),
    ("hotel", "Two guests walk from the bar across to 103.", "room_103"),
    ("stadium", "Two fans stroll back to 101 at half time.", "block_101"),
])
def test_a_bare_room_number_after_to_is_the_room(read, world, prompt, destination):
    (g,) = read(world, prompt).groups
    assert g.intent == "walk" and g.destination == destination
