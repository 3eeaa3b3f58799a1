"""Hobbling, limping or stumbling clear of the robot is avoiding it, even when the parser takes the verb
for a noun after "with a walking frame" (language/robot_shrinking.py); a fronted "Looking uneasy," keeps
the fright (Scared)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "Looking uneasy, an old woman with a walking frame hobbles clear of the robot."),
    ("museum", "Looking nervous, a pensioner with a stick limps well clear of the robot."),
    ("station", "A man with crutches staggers away from the robot."),
])
def test_hobbling_clear_of_the_robot_avoids_it(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.robot_interaction, g.robot_reaction) == ("robot", "avoid", "Scared")
