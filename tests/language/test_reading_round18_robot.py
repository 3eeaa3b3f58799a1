"""Robot classes of round 18, each with sentences of its own over at least two worlds (none from the
understanding sets): a verb of a manner of walking going after or to the robot is following or
coming to it; the robot's clause typed as chat gives its task and place; a person moved along by
another (wheeled, pushed, fetched) is a second group, and what they ride is no unknown place."""

from __future__ import annotations

import pytest


# ---- A. a manner of walking after or to the robot is a reaction to it ------------------------------

@pytest.mark.parametrize("world,prompt,interaction", [
    ("mall", "Two inquisitive boys trot after the robot past the cinema.", "follow"),
    ("hospital", "A nosy visitor trots after the robot along the corridor.", "follow"),
    ("station", "A couple of bored teens mooch after the robot along the concourse.", "follow"),
    ("office", "A pair of interns scamper over to the robot.", "approach"),
    ("office", "An inquisitive intern makes a beeline for the robot by the kitchen.", "approach"),
    ("airport", "Some excited kids make a beeline for the robot.", "approach"),
    ("hospital", "An eager student nurse hurries straight for the robot.", "approach"),
    ("zoo", "Two curious keepers head straight for the robot.", "approach"),
])
def test_a_manner_of_walking_to_or_after_the_robot_reacts_to_it(read, world, prompt, interaction):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.robot_interaction, group.robot_reaction) == ("robot", interaction, "Curious")


@pytest.mark.parametrize("world,prompt", [
    ("mall", "A pair of nosy toddlers trot after the robot round the food court."),
    ("museum", "A pair of little boys scamper after the robot round the gift shop."),
    ("zoo", "A couple of curious kids toddle after the robot round the gift shop."),
])
def test_the_robot_gone_after_is_no_robot_clause(read, world, prompt):
    reading = read(world, prompt)
    assert reading.robot is None and reading.groups[0].robot_interaction == "follow"


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "An angry relative deliberately parks his wheelchair across the robot's route."),
    ("museum", "A cross visitor deliberately leaves her pushchair across the robot's route."),
    ("town_hall", "An irate councillor near the reception desk plants his briefcase across the robot's route."),
])
def test_something_put_across_the_robots_route_blocks_it(read, world, prompt):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.robot_interaction, group.robot_reaction) == ("robot", "block", "Threatening")


@pytest.mark.parametrize("world,prompt", [
    ("museum", "Two children run after the guide while the robot waits by the cloakroom."),
    ("airport", "A man heads for gate b1 as the robot passes."),
])
def test_going_after_or_to_someone_else_is_no_reaction(read, world, prompt):
    assert read(world, prompt).groups[0].robot_interaction is None


# ---- B. the robot's clause in chat ------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,task,place", [
    ("museum", "abt 10 kids at the gift shop, robot shd wait @ cloakroom", "wait", "cloakroom"),
    ("zoo", "6 keepers @ penguin beach, robo shd wait by gift shop", "wait", "gift_shop"),
    ("hospital", "2 nurses @ reception, rbt waits by pharmacy", "wait", "pharmacy"),
    ("airport", "loads of ppl at check in, robo go 2 gate b1", "cross", "gate_b1"),
    ("station", "robot shd wait @ ticket office, 5 ppl on platform 1", "wait", "ticket_office"),
])
def test_the_robots_chat_clause_gives_its_task_and_place(read, world, prompt, task, place):
    robot = read(world, prompt).robot
    assert robot is not None and robot.task == task
    assert place in (robot.location, robot.destination)


@pytest.mark.parametrize("world,prompt", [
    ("mall", "3 guards frm security office goin to food court, bot to follow em"),
    ("office", "bot to follow em, 2 devs goin to kitchen"),
    ("library", "4 students headin to the cafe, robo to follow em"),
])
def test_the_robot_to_follow_them_in_chat_follows(read, world, prompt):
    reading = read(world, prompt)
    assert reading.robot is not None and reading.robot.task == "follow"
    assert reading.groups[0].destination is not None


# ---- C. a person moved along by another ------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("zoo", "A keeper wheels a boy with a sprained wrist from the penguin beach to the gift shop.",
     "penguin_beach", "gift_shop"),
    ("hospital", "A nurse wheels an elderly gent on a stretcher from the ward to the pharmacy.", "ward_a", "pharmacy"),
    ("museum", "A guard pushes an old gent in a wheelchair from the cloakroom down to the cafe.", "cloakroom", "cafe"),
    ("station", "A porter fetches the old man from the ticket office and takes him to platform 2.",
     "ticket_office", "platform_2"),
    ("office", "The office manager collects the new intern from reception and brings her to the kitchen.",
     "reception", "kitchen"),
    ("care_home", "A carer fetches a resident from the lounge and takes her to the dining room.", "lounge",
     "dining_room"),
    ("hospital", "A nurse fetches the new starter from the lobby and takes her to the ward.", "entrance_lobby",
     "ward_a"),
    ("town_hall", "A clerk fetches the new joiner from the foyer and brings him to the council chamber.", "foyer",
     "council_chamber"),
])
def test_a_person_moved_along_is_a_second_group(read, world, prompt, start, destination):
    reading = read(world, prompt)
    assert len(reading.groups) == 2 and not reading.unknown_places
    mover, moved = reading.groups
    assert (mover.count.kind, mover.count.value, mover.intent) == ("exact", 1, "walk")
    assert (mover.start, mover.destination) == (start, destination)
    assert (moved.count.value, moved.intent, moved.robot_reaction) == (1, "follow", None)


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "A porter pushes an elderly gent on a gurney from the ward to the pharmacy."),
    ("airport", "A steward wheels an elderly gent on a buggy from check-in along to gate b1."),
])
def test_what_the_moved_person_rides_is_no_unknown_place(read, world, prompt):
    assert not read(world, prompt).unknown_places


def test_fetching_a_thing_makes_no_second_group(read):
    assert len(read("hospital", "A nurse fetches a coffee from the cafe.").groups) == 1


# ---- D. what the robot has to do is its task ------------------------------------------------------

@pytest.mark.parametrize("world,prompt,task,place", [
    ("hospital", "The robot needs to wait by the pharmacy while two nurses chat at reception.", "wait", "pharmacy"),
    ("museum", "The robot has to patrol the great hall; three guards stand at the entrance.", "patrol", "great_hall"),
    ("mall", "The robot is supposed to wait outside the cinema while ten teens hang around the food court.", "wait",
     "east_mall"),  # outside X is the zone its door opens to
    ("station", "robot gotta wait @ ticket office, 5 ppl on platform 1", "wait", "ticket_office"),
    ("hospital", "Tell the robot to wait by the pharmacy.", "wait", "pharmacy"),
])
def test_what_the_robot_has_to_do_is_its_task(read, world, prompt, task, place):
    robot = read(world, prompt).robot
    assert robot is not None and (robot.task, robot.location) == (task, place)
