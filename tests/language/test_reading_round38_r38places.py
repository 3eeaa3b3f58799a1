"""Place classes of round 38, each with sentences of its own over at least two worlds (none from the
understanding sets): a way out said by the room it is in ("the party room fire door", "the sports bar
fire door"): the room's own exit, where people go, not a room they pass; the robot's own trip said after
what it passes ("weaves through kids milling by the skeleton, bound for the café"): a crossing to it."""

from __future__ import annotations

import pytest


# ---- 1. "<room> fire door": the room's own way out --------------------------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("trampoline_park", "Twelve jumpers on the dodgeball court hurry out via the ninja course emergency door.",
     "ninja_fire_exit"),
    ("bowling_alley", "Ten kids in the party room leave by the party room fire door.", "party_room_fire_exit"),
    ("bowling_alley", "A dozen drinkers walk out through the sports bar fire door.", "bar_fire_exit"),
    ("aquarium", "Forty visitors pile out via the coral reef gallery fire door.", "reef_fire_exit"),
    ("bowling_alley", "The party hurries out via the party room emergency exit.", "party_room_fire_exit"),
    ("art_gallery", "Twenty visitors shuffle out via the temporary exhibition fire door.", "temporary_fire_exit"),
    ("museum", "The audience file out through the auditorium emergency door.", "auditorium_exit"),
])
def test_a_way_out_said_by_its_room_is_where_people_go(read, world, prompt, destination):
    (g,) = read(world, prompt).groups
    assert g.destination == destination
    assert destination not in g.via


# ---- 2. the robot's trip said after what it passes ----------------------------------------------------

@pytest.mark.parametrize("world,prompt,destination,via", [
    ("museum", "The robot weaves through schoolkids who mill under the whale skeleton, bound for the café.", "cafe",
     "whale_skeleton"),
    ("mall", "The robot glides past shoppers wandering around the fountain, bound for the food court.", "food_court",
     "fountain"),
    ("mall", "The robot threads through teens milling around the fountain, on its way to the cinema.",
     "cinema_lobby", "fountain"),
    ("airport", "The robot zigzags past backpackers wandering about the information desk, bound for gate B1.",
     "gate_b1", "information_desk"),
    ("hospital", "The robot edges past a cluster of visitors drifting around the cafeteria, headed for ward B.",
     "ward_b", "cafeteria"),
])
def test_the_robots_trip_after_people_it_passes_is_a_crossing(read, world, prompt, destination, via):
    robot = read(world, prompt).robot
    assert robot is not None
    assert (robot.task, robot.destination, robot.location) == ("cross", destination, None)
    assert via in robot.via


@pytest.mark.parametrize("world,prompt,intent,location", [
    ("mall", "The robot threads through a crowd of teenagers hanging around the fountain, headed for the cinema.",
     "wait", "fountain"),
    ("office", "The robot slips between two engineers arguing at the kitchen, heading for meeting room 2.", "converse",
     "kitchen"),
    ("airport", "The robot zigzags through a gaggle of backpackers loitering at the information desk, en route to "
     "gate B1.", "wait", "information_desk"),
    ("hospital", "The robot edges past two porters chatting in the cafeteria, heading for ward B.", "converse",
     "cafeteria"),
])
def test_the_people_passed_on_the_robots_trip_stay_where_they_are(read, world, prompt, intent, location):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.start, g.destination, g.location) == (intent, None, None, location)


# ---- guards: readings that must stay ---------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("museum", "Ten visitors leave via the east fire door.", "fire_exit"),
    ("hospital", "Two porters walk out through the west fire door.", "west_emergency_exit"),
    ("aquarium", "Forty visitors pile out via the reef fire exit.", "reef_fire_exit"),
])
def test_a_way_out_said_by_its_side_stays(read, world, prompt, destination):
    (g,) = read(world, prompt).groups
    assert g.destination == destination


@pytest.mark.parametrize("world,prompt,task,destination,location", [
    ("hospital", "The robot heads for ward B.", "cross", "ward_b", None),
    ("mall", "The robot waits by the fountain for shoppers bound for the cinema.", "wait", None, "fountain"),
    ("mall", "The robot patrols the food court.", "patrol", None, "food_court"),
    ("hospital", "The robot glides through a crowd of visitors in the cafeteria, bound for ward B.", "cross",
     "ward_b", None),
])
def test_the_robots_plain_tasks_stay(read, world, prompt, task, destination, location):
    robot = read(world, prompt).robot
    assert robot is not None
    assert (robot.task, robot.destination, robot.location) == (task, destination, location)


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("mall", "The robot passes two teens at the fountain who are heading for the cinema.", "fountain", "cinema_lobby"),
    ("hospital", "Two porters in the cafeteria head for ward B as the robot waits by the lifts.", "cafeteria",
     "ward_b"),
])
def test_people_who_go_somewhere_themselves_keep_their_trip(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.start, g.destination) == (start, destination)
