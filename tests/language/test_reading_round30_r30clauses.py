"""Clause classes of round 30, each with sentences of its own over at least two worlds (none from the
understanding sets): a wait said in chat shorthand with a duration, then a move; a zone cleared in the
passive; crowding round a thing after moving; steering wide of or hanging back from the robot; a
feeling set apart from its clause; the person the robot guides, with modifiers of their own."""

from __future__ import annotations

import pytest


# ---- 1. a chat wait with a duration, then a move ----------------------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination,seconds", [
    ("hospital", "porter @ pharmacy 10 mins then off to the cafeteria", "pharmacy", "cafeteria", 600.0),
    ("hospital", "cleaner stuck at the toilets 5 mins then heads to the lifts", "restroom_men", "elevator_hall", 300.0),
    ("mall", "nurse at pharmacy 10 mins then off to the cafe", "pharmacy", "coffee_counter", 600.0),
    ("job_centre", "claimant stuck @ printer 3 mins then off to the water cooler", "printer", "water_cooler", 180.0),
    ("library", "student sat at the issue desk 4 mins then off to the cafe", "issue_desk", "cafe", 240.0),
])
def test_a_chat_wait_with_a_duration_then_a_move(read, world, prompt, start, destination, seconds):
    (g,) = read(world, prompt).groups
    assert (g.count.kind, g.count.value) == ("exact", 1)
    assert (g.start, g.destination, g.wait_seconds) == (start, destination, seconds)


# ---- 2. a zone cleared in the passive -------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,start", [
    ("station", "Smoke is seen on platform 1, and the thirty commuters stood there are cleared off it.", "platform_1"),
    ("mall", "A leak is reported in the food court, and the forty diners stood there are cleared off it.", "food_court"),
    ("library", "A pipe bursts in the reading room, and the dozen students working there are cleared from it.",
     "reading_room"),
    ("hospital", "A leak is reported in the cafeteria, and the twenty visitors stood there are cleared off it.",
     "cafeteria"),
    ("job_centre", "Smoke is reported in the training room, and the ten trainees sat there are cleared off it.",
     "training_room"),
])
def test_a_zone_cleared_in_the_passive_is_evacuated(read, world, prompt, start):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.start) == ("evacuate", start)


@pytest.mark.parametrize("world,prompt,start", [
    ("station", "A fire alarm sounds on platform 1, and the thirty commuters waiting there are cleared off it.",
     "platform_1"),
    ("mall", "Smoke is spotted in the food court, and the forty diners sat there get cleared out of it.", "food_court"),
])
def test_a_cleared_zone_already_read_keeps_its_evacuation(read, world, prompt, start):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.start) == ("evacuate", start)


# ---- 3. crowding round a thing after moving -----------------------------------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("car_showroom", "A dozen buyers wander in through the forecourt doors and cluster round the SUV.", "display_suv"),
    ("car_showroom", "Six punters drift in and gather round the hatchback.", "display_hatchback"),
    ("mall", "A dozen teens rush over and cluster round the fountain.", "fountain"),
    ("mall", "Ten kids run across the atrium and huddle around the fountain.", "fountain"),
])
def test_crowding_round_a_thing_after_moving_goes_to_it(read, world, prompt, destination):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.destination) == ("walk", destination)


def test_crowding_round_a_thing_without_moving_waits_there(read):
    (g,) = read("car_showroom", "Six buyers gather round the hatchback.").groups
    assert (g.intent, g.location) == ("wait", "display_hatchback")
    (g,) = read("mall", "Ten kids chat and huddle around the fountain.").groups
    assert g.intent == "converse"


# ---- 4. steering wide of the robot, hanging back from it --------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("mall", "Near the fountain, a nervous dad swerves his pushchair wide of the robot."),
    ("supermarket", "A pensioner steers her trolley well clear of the robot."),
    ("hospital", "A porter veers his trolley wide of the robot in the corridor."),
    ("library", "A shy boy hangs back from the robot by the issue desk."),
    ("station", "Two tourists hang back from the robot on platform 1."),
])
def test_steering_wide_of_or_hanging_back_from_the_robot_avoids_it(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.robot_interaction, g.robot_reaction) == ("robot", "avoid", "Scared")


def test_steering_somewhere_else_keeps_its_walk(read):
    (g,) = read("supermarket", "A pensioner steers her trolley to the tills.").groups
    assert g.robot_interaction is None


# ---- 5. a feeling set apart from its clause --------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,reaction", [
    ("mall", "Spellbound, a little girl gawps at the robot from the bench.", "Curious"),
    ("library", "Intrigued, a pensioner peers at the robot over her glasses.", "Curious"),
    ("hospital", "Wary, an old man eyes the robot from his bed.", "Scared"),
    ("station", "A commuter stares at the robot, nervous.", "Scared"),
    ("car_showroom", "Intrigued, a salesman stares at the robot by the SUV.", "Curious"),
])
def test_a_feeling_set_apart_colours_a_look(read, world, prompt, reaction):
    (g,) = read(world, prompt).groups
    assert (g.robot_interaction, g.robot_reaction) == ("look", reaction)


def test_a_look_with_no_feeling_stays_surprised(read):
    (g,) = read("mall", "A little girl gawps at the robot from the bench.").groups
    assert (g.robot_interaction, g.robot_reaction) == ("look", "Surprised")
    (g,) = read("hospital", "Wary, an old man backs away from the robot.").groups
    assert (g.robot_interaction, g.robot_reaction) == ("avoid", "Scared")


# ---- 6. the person the robot guides, with modifiers of their own ---------------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("job_centre", "The robot guides a nervous first-time visitor from the lobby to the training room.",
     "training_room"),
    ("mall", "The robot escorts a nervous first-time visitor from the entrance to the pharmacy.", "pharmacy"),
    ("hospital", "The robot leads a confused long-stay patient to the cafeteria.", "cafeteria"),
    ("library", "The robot takes a flustered first-year student to the reading room.", "reading_room"),
])
def test_the_person_the_robot_guides_follows_it(read, world, prompt, destination):
    reading = read(world, prompt)
    (g,) = reading.groups
    assert g.robot_interaction == "follow"
    assert reading.robot is not None and reading.robot.destination == destination
