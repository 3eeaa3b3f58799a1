"""Robot classes of round 22, each with sentences of its own over at least two worlds (none from the
understanding sets): a reaction said by an idiom or the whole body; a reaction clause the robot's
own clause times, before or after it ("As the robot ..., X ...", "... whenever the robot comes near");
the robot staying put said in other words; people who let or have the robot take them somewhere."""

from __future__ import annotations

import pytest


# ---- 1. a reaction said by an idiom or the whole body -------------------------------------------------

@pytest.mark.parametrize("world,prompt,interaction", [
    ("mall", "A shy toddler nearly jumps out of his skin as the robot rolls past the fountain.", "look"),
    ("hotel", "The night porter leaps out of his skin when the robot glides past the bar.", "look"),
    ("hospital", "A nervous patient stops dead in her tracks as the robot approaches the pharmacy.", "look"),
    ("museum", "An old gent does a double take as the robot trundles by.", "look"),
    ("mall", "Three rowdy teenagers hem the robot in by the food court.", "block"),
    ("office", "Two grumpy managers box the robot in near the kitchen.", "block"),
    ("library", "A cross librarian shoos the robot away from the reading room.", "block"),
    ("station", "A grumpy guard waves the robot away from the ticket office.", "block"),
    ("zoo", "A surly keeper chases the robot off near the gift shop.", "block"),
    ("hospital", "A jumpy visitor dives out of the way as the robot rolls down the corridor.", "avoid"),
])
def test_an_idiom_names_the_reaction(read, world, prompt, interaction):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.robot_interaction) == ("robot", interaction)


@pytest.mark.parametrize("world,prompt", [
    ("office", "A courier jumps out of the lift at the third floor while the robot waits by the kitchen."),
    ("mall", "A gang of lads box up their shopping at the food court while the robot waits by the fountain."),
])
def test_no_idiom_no_reaction(read, world, prompt):
    assert read(world, prompt).groups[0].robot_interaction is None


# ---- 4. a reaction clause the robot's clause times --------------------------------------------------

@pytest.mark.parametrize("world,prompt,interaction", [
    ("mall", "As the robot rolls past the fountain, a toddler hides behind his mum.", "avoid"),
    ("office", "Whenever the robot comes near, the new intern ducks behind her monitor.", "avoid"),
    ("hotel", "The cleaner scurries away whenever the robot approaches.", "avoid"),
    ("station", "When the robot rolls onto the concourse, an old man freezes.", "look"),
    ("museum", "Whenever the robot trundles close, two schoolgirls hide behind a pillar.", "avoid"),
    ("zoo", "A keeper's boy scarpers off whenever the robot comes near.", "avoid"),
    ("zoo", "As the robot trundles past the penguins, a little girl nearly jumps out of her skin.", "look"),
])
def test_a_reaction_the_robot_times_is_the_groups(read, world, prompt, interaction):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.robot_interaction) == ("robot", interaction)


@pytest.mark.parametrize("world,prompt", [
    ("station", "About forty commuters pour off platform 1 towards the gates while the robot patrols the concourse."),
    ("hospital", "A porter heads back to the ward as the robot waits by the lift."),
])
def test_a_going_the_robot_only_accompanies_is_no_reaction(read, world, prompt):
    assert read(world, prompt).groups[0].robot_interaction is None


# ---- 3. the robot staying put said in other words ---------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("mall", "The robot holds position by the fountain while two cleaners mop the food court.", "fountain"),
    ("office", "The robot holds its position near the kitchen while a manager paces the corridor.", "kitchen"),
    ("airport", "The robot keeps its station beside gate b1 while four pilots chat at the cafe.", "gate_b1"),
    ("museum", "The robot holds its ground by the cloakroom as a school party files past.", "cloakroom"),
])
def test_keeping_a_post_is_a_wait_there(read, world, prompt, place):
    robot = read(world, prompt).robot
    assert robot is not None and (robot.task, robot.location) == ("wait", place)


@pytest.mark.parametrize("world,prompt,place", [
    ("hospital", "The robot waits by the pharmacy while a cleaner mops out the canteen.", "cafeteria"),
    ("mall", "A cleaner sweeps out the food court.", "food_court"),
    ("office", "Two cleaners scrub out the kitchen.", "kitchen"),
])
def test_cleaning_out_a_place_is_being_there(read, world, prompt, place):
    group = read(world, prompt).groups[0]
    assert (group.location, group.start) == (place, None)


# ---- 2. people who let or have the robot take them somewhere ----------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "A lost visitor lets the robot lead him from reception to the pharmacy.", "reception_desk", "pharmacy"),
    ("mall", "A tired shopper lets the robot guide her from the fountain to the food court.", "fountain", "food_court"),
    ("museum", "An old man has the robot show him to the cloakroom from the gift shop.", "gift_shop", "cloakroom"),
    ("station", "A tourist asks the robot to walk him from the ticket office to platform 1.", "ticket_office",
     "platform_1"),
    ("airport", "A confused passenger asks the robot to take her to gate b1.", None, "gate_b1"),
])
def test_one_the_robot_is_asked_to_take_follows_it(read, world, prompt, start, destination):
    reading = read(world, prompt)
    group = reading.groups[0]
    assert (group.intent, group.robot_interaction) == ("robot", "follow")
    assert reading.robot is not None and (reading.robot.task, reading.robot.start, reading.robot.destination) == (
        "cross", start, destination)
