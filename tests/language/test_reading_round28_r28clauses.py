"""Clause classes of round 28, each with sentences of its own over at least two worlds (none from the
understanding sets): a queue said by the line people form or stand in with words between ("form a long
line"); hiding by a quick move behind something when the robot's clause times it, with time said by
"every time" or "the moment"; verbs of lying or lolling about are waiting; a wait said by the time to
come before people go ("heading to platform 1 in 5 mins"); a wait that ends when someone with a room of
their own calls the waiting in; sticking to the robot is following it, keeping it off or away is
blocking it."""

from __future__ import annotations

import pytest


# ---- 1. a queue said by the line made or stood in, with words between -------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("hospital", "Ten patients form a long queue at the pharmacy."),
    ("airport", "Forty passengers form a long line at gate A1."),
    ("tv_studio", "Around thirty extras form a long line at the servery."),
    ("mall", "Six shoppers stand in a neat line outside the toy store."),
    ("mall", "Six shoppers join the long queue at the cafe."),
])
def test_a_line_formed_or_stood_in_is_a_queue(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.intent == "queue"


@pytest.mark.parametrize("world,prompt,intent", [
    ("hospital", "Ten patients line up at the pharmacy.", "queue"),
    ("mall", "Six shoppers join the back of the queue at the cafe.", "queue"),
    ("hospital", "A nurse stands in the main waiting room.", "wait"),
    ("airport", "Two cleaners walk along the line of seats at gate A1.", "walk"),
])
def test_queue_phrases_and_lines_of_things_keep_their_reading(read, world, prompt, intent):
    assert read(world, prompt).groups[0].intent == intent


# ---- 2. hiding by a quick move when the robot's clause times it --------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("residential", "Our little one shrieks and dives behind the sofa every time the robot beeps."),
    ("hospital", "A boy darts under the chairs in the main waiting room each time the robot comes near."),
    ("mall", "A little girl scrambles behind a bench as the robot rolls past."),
    ("zoo", "A small boy jumps behind his dad whenever the robot comes close."),
    ("aquarium", "A toddler dives under the benches whenever the robot beeps."),
])
def test_a_quick_move_behind_something_timed_by_the_robot_avoids_it(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert (g.robot_interaction, g.robot_reaction) == ("avoid", "Scared")


@pytest.mark.parametrize("world,prompt", [
    ("mall", "A boy dives behind a bench in the food court."),
    ("hospital", "A man sits in the main waiting room every time the robot passes."),
])
def test_a_move_behind_something_untimed_or_a_stay_has_no_reaction(read, world, prompt):
    assert read(world, prompt).groups[0].robot_interaction is None


# ---- 3. lying or lolling about: waiting ---------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("fire_station", "Six crew on days sprawl across the sofas in the mess room.", "tv_sofas"),
    ("hall_of_residence", "Four freshers sprawl across the sofas in the common room.", "common_room_sofas"),
    ("hospital", "Three porters sprawl across the chairs in the main waiting room.", None),
    ("residential", "The twins flop onto the sofa in the living room.", "sofa"),
])
def test_lying_or_lolling_about_is_waiting(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert g.intent == "wait"
    assert not g.via
    if location is not None:
        assert g.location == location


@pytest.mark.parametrize("world,prompt,intent", [
    ("hospital", "A porter lays a blanket on the trolley and walks to the pharmacy.", "walk"),
    ("mall", "Two teenagers lounge on the benches in the food court.", "wait"),
    ("office", "A sulky intern slouches into the kitchen.", "walk"),
    ("hospital", "A bored teenager slouches off to the cafeteria.", "walk"),
])
def test_laying_a_thing_or_lounging_keeps_its_reading(read, world, prompt, intent):
    assert read(world, prompt).groups[0].intent == intent


# ---- 4. a wait said by the time to come before people go ---------------------------------------------------

@pytest.mark.parametrize("world,prompt,seconds", [
    ("station", "4 girls in the cafe, heading to platform 2 in 10 mins", 600.0),
    ("airport", "A family at the cafe will go to gate A1 in half an hour.", 1800.0),
    ("hospital", "Two nurses in the main waiting room head to the pharmacy in 10 minutes' time.", 600.0),
    ("ferry_terminal", "A coach party in the departure lounge are boarding in twenty minutes.", 1200.0),
])
def test_a_time_to_come_before_going_is_a_wait_first(read, world, prompt, seconds):
    (g,) = read(world, prompt).groups
    assert g.wait_seconds == seconds


@pytest.mark.parametrize("world,prompt", [
    ("mall", "Four teens in the food court walk to the toy store in under five minutes."),
    ("hospital", "Two nurses walk to the pharmacy in 10 minutes and then wait there."),
    ("hospital", "The head nurse in the main waiting room will be in the pharmacy in 10 minutes."),
])
def test_a_speed_or_a_time_mid_clause_is_no_wait(read, world, prompt):
    assert read(world, prompt).groups[0].wait_seconds is None


# ---- 5. a wait ends in the room of whoever calls the waiting in ---------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "A nervous man sits in the main waiting room until the doctor calls him in.", "main_waiting_room",
     "doctors_office"),
    ("police_station", "A witness waits at the front counter for ten minutes until the sergeant calls her through.",
     "front_counter", "sergeants_office"),
    ("office", "Two candidates wait in the lobby until the manager calls them in.", "reception", "manager_office"),
    ("dental_clinic", "Two patients sit in the waiting room until the hygienist calls them in.", "waiting_room",
     "hygienist_room"),
])
def test_being_called_in_ends_the_wait_in_the_callers_room(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.start, g.destination) == (start, destination)


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "A man waits in the main waiting room until the doctor arrives."),
    ("dental_clinic", "A boy sits in the waiting room until his mum calls him over."),
])
def test_a_wait_ended_otherwise_goes_nowhere(read, world, prompt):
    assert read(world, prompt).groups[0].destination is None


# ---- 6. sticking to the robot follows it; keeping it off or away blocks it ----------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("zoo", "A lad in a lion costume sticks to the robot like glue around the reptile house."),
    ("museum", "A small boy sticks close to the robot from the great hall to the cafe."),
    ("mall", "A toddler stays glued to the robot all the way to the food court."),
    ("aquarium", "A boy in a diver's mask sticks to the robot like glue from the ticket hall to the shark tunnel."),
])
def test_sticking_to_the_robot_follows_it(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert (g.robot_interaction, g.robot_reaction) == ("follow", "Curious")


@pytest.mark.parametrize("world,prompt", [
    ("museum", "Two guards stand shoulder to shoulder in the doorway to keep the robot out of the great hall."),
    ("station", "A gang of fans form a human chain across platform 1 to keep the robot away."),
    ("mall", "A security guard stands by the toy store to keep the robot out."),
    ("ice_rink", "Three young skaters link arms across the rink to keep the robot off the ice."),
])
def test_keeping_the_robot_off_or_away_blocks_it(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert (g.robot_interaction, g.robot_reaction) == ("block", "Threatening")


@pytest.mark.parametrize("world,prompt", [
    ("mall", "A boy sticks to the path as the robot passes."),
    ("hospital", "A nurse keeps the robot's tray off the floor."),
])
def test_sticking_to_a_path_or_keeping_a_thing_off_has_no_reaction(read, world, prompt):
    assert read(world, prompt).groups[0].robot_interaction is None


# ---- 7. the robot's way as its own journey: no one stands in it, and its places are not the people's ----------

@pytest.mark.parametrize("world,prompt,location", [
    ("hospital", "The robot edges past ten visitors chatting in the main waiting room on its way to the pharmacy.",
     "main_waiting_room"),
    ("mall", "The robot weaves between a dozen shoppers browsing in the food court on its way to the toy store.",
     "food_court"),
    ("station", "The robot squeezes past thirty commuters waiting on platform 1 on its way to the exit.", "platform_1"),
    ("hall_of_residence", "The robot squeezes past sixty freshers milling in the foyer on its way to the lifts.",
     None),
])
def test_people_passed_on_the_robots_way_neither_block_it_nor_go_its_way(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert g.robot_interaction is None
    assert g.destination is None
    if location is not None:
        assert g.location == location


@pytest.mark.parametrize("world,prompt", [
    ("station", "A drunk stands in the robot's way on platform 1."),
    ("mall", "A boy steps into the robot's path in the food court."),
])
def test_standing_in_the_robots_way_still_blocks_it(read, world, prompt):
    assert read(world, prompt).groups[0].robot_interaction == "block"
