"""Round 21 of the reader's clauses and places: a robot that patrols between two places, or back and
forth between them, keeps both on its round (the first where it patrols, the second passed)."""

import pytest


@pytest.mark.parametrize("world,prompt,location,via", [
    ("hospital", "The robot patrols between the pharmacy and the cafeteria while 3 visitors sit in the waiting room.",
     "pharmacy", ("cafeteria",)),
    ("hospital", "The robot patrols back and forth between radiology and the entrance lobby.",
     "radiology", ("entrance_lobby",)),
    ("airport", "Two pilots chat at gate A1 as the robot patrols back and forth between duty free and the concourse.",
     "duty_free", ("concourse",)),
    ("library",
     "The robot keeps patrolling between the entrance foyer and the lending hall.",
     "entrance_foyer", ("lending_hall",)),
])
def test_a_patrol_between_two_places_keeps_both(read, world, prompt, location, via):
    robot = read(world, prompt).robot
    assert robot is not None and robot.task == "patrol"
    assert robot.location == location and robot.via == via


@pytest.mark.parametrize("world,prompt,destination,via", [
    ("hospital", "Two nurses walk to the cafeteria before going to the pharmacy.", "pharmacy", ("cafeteria",)),
    ("hospital", "A porter pushes a trolley to radiology and afterwards goes to the pharmacy.", "pharmacy", ("radiology",)),
    ("airport", "Four passengers walk to the duty free before going to gate A2.", "gate_a2", ("duty_free",)),
    ("airport", "A family heads to the toilets, later heading to gate A1.", "gate_a1", ("toilets",)),
])
def test_a_later_destination_is_where_the_group_ends(read, world, prompt, destination, via):
    (g,) = read(world, prompt).groups
    assert g.destination == destination and g.via == via
