"""Anger at the robot while coming up to it, by a word of anger on the subject ("an irate chef"), by
shouting at it, or by telling it to clear off, is a threat: Threatening, still an approach
(language/angry_approach.py). Coming up to it calmly stays Curious."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "An irate porter strides over to the robot and shouts at it."),
    ("station", "A guard walks up to the robot on the concourse and tells it to get lost."),
    ("museum", "An angry attendant goes over to the robot and screams at it to go away."),
    ("mall", "A security guard comes up to the robot and orders it to clear off."),
])
def test_anger_at_the_robot_when_coming_up_is_a_threat(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert (g.robot_interaction, g.robot_reaction) == ("approach", "Threatening")


def test_coming_up_and_talking_calmly_stays_curious(read):
    (g,) = read("mall", "A little girl walks up to the robot and says hello to it.").groups
    assert (g.robot_interaction, g.robot_reaction) == ("approach", "Curious")
