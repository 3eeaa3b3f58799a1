"""Going at the robot to hurt or insult it ("lunges at the robot", "swings at it", "charges at the robot",
"lashes out at it") is a threat (HuNavSim's Threatening, the reader's block), not a look as other things done
"at" it are (language/hostile_gestures.py). Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "A drunk lurches over and swings at the robot in the lobby."),
    ("mall", "A furious shopper charges at the robot by the fountain."),
    ("museum", "A bored teenager lashes out at the robot in the main hall."),
    ("station", "Yelling, a man lunges at the robot near the ticket machines."),
])
def test_going_at_the_robot_is_a_threat(read, world, prompt):
    g, = read(world, prompt).groups
    assert (g.robot_interaction, g.robot_reaction) == ("block", "Threatening")


@pytest.mark.parametrize("world,prompt", [
    ("mall", "A toddler waves at the robot by the fountain."),
    ("airport", "A man swings his suitcase onto the belt and glances at the robot."),
])
def test_other_things_done_at_the_robot_stay_a_look(read, world, prompt):
    g, = read(world, prompt).groups
    assert (g.robot_interaction, g.robot_reaction) == ("look", "Surprised")
