"""Fleeing off to a place as the robot comes is avoiding it (Scared), with a verb of fright or a fear
said before the subject; a robot's verb said as a noun ("the far corner") is no cornering of the robot.
Real spaCy, real worlds and the eval worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt", [
    ("museum", "Petrified, a little boy in the gift shop runs off to the cafe when the robot rolls in."),
    ("hospital", "An old man in the cafeteria scuttles off into the far corner as soon as the robot rolls in."),
    ("library", "Frightened, a small girl by the returns desk dashes off to the quiet corner when the robot appears."),
])
def test_fleeing_off_to_a_place_as_the_robot_comes_is_avoiding_it(read, world, prompt):
    group = read(world, prompt).groups[0]
    assert (group.robot_interaction, group.robot_reaction) == ("avoid", "Scared")


def test_a_far_corner_is_no_cornering_of_the_robot(read):
    group = read("office", "An intern walks to the far corner of the kitchen while the robot waits.").groups[0]
    assert group.robot_interaction != "block"
