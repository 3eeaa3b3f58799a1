"""Round 44: taking fright at the robot, or seeing it and going off to hide, is avoiding it (Scared), not
only looking at it."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("hotel", "A little girl sees the robot and scurries off to hide."),
    ("hotel", "A page boy is startled by the robot and runs off to hide behind the bar."),
    ("museum", "A small boy takes fright at the robot."),
    ("mall", "A toddler spots the robot and darts away to hide behind the fountain."),
])
def test_hiding_from_the_robot_is_avoiding_it(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.robot_interaction, g.robot_reaction) == ("robot", "avoid", "Scared")


@pytest.mark.parametrize("world,prompt", [
    ("hotel", "A little girl stares at the robot by the lifts."),
    ("mall", "A toddler waves at the robot and then hides behind his dad."),
])
def test_looking_or_hiding_where_one_is_is_still_a_look(read, world, prompt):
    g = read(world, prompt).groups[0]
    assert g.robot_interaction == "look"
