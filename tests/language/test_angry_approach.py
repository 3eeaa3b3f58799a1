"""Coming up to the robot in anger, by a word of anger set before the subject or by storming at it and
striking it, is a threat: Threatening, still an approach (language/angry_approach.py). Coming up to it
with no anger stays Curious."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "Furious, a visitor marches up to the robot and thumps its screen."),
    ("station", "A commuter storms over to the robot and kicks it."),
    ("museum", "Livid, a tourist strides over to the robot and hammers on its lid."),
    ("recycling_centre", "Fuming, a man in a van storms up to the robot at the weighbridge."),
])
def test_coming_up_to_the_robot_in_anger_is_a_threat(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert (g.robot_interaction, g.robot_reaction) == ("approach", "Threatening")


def test_coming_up_to_the_robot_calmly_stays_curious(read):
    (g,) = read("mall", "A little boy runs up to the robot and pats its casing.").groups
    assert (g.robot_interaction, g.robot_reaction) == ("approach", "Curious")
