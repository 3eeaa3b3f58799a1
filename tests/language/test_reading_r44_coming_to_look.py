"""Round 44: going over to the robot in order to look at it ("drift across to get a proper squint at the
robot", "wander over for a closer look at it") is approaching it (Curious); a look with no going over
("stop to look at the robot", "twist round to peer at it") stays a look."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("hotel", "Two porters come over to look at the robot."),
    ("office", "Two developers wander over for a closer look at the robot."),
    ("station", "A few commuters drift across to have a proper look at the robot."),
])
def test_going_over_to_look_is_approaching(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert (g.robot_interaction, g.robot_reaction) == ("approach", "Curious")


@pytest.mark.parametrize("world,prompt", [
    ("hotel", "Two porters stop to look at the robot."),
    ("museum", "On the bench in the great hall, three pensioners twist round to peer at our robot."),
])
def test_looking_without_going_over_is_a_look(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.robot_interaction == "look"
