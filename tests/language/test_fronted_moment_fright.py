"""A fronted "The moment / As soon as the robot ..." times the clause after it, and a fright there
(a scream, diving or crawling under something) is avoiding the robot, Scared
(language/fronted_timers.py); a squeal of delight is not."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("residential", "As soon as the robot rolls into the kitchen, the toddler screams and hides behind the sofa."),
    ("museum", "As soon as the robot appears, a small boy screams."),
    ("residential", "The moment the robot opens the door, our son dives under the bed."),
])
def test_a_fright_timed_by_a_fronted_robot_clause_avoids_it(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.robot_interaction, g.robot_reaction) == ("robot", "avoid", "Scared")


def test_a_squeal_of_delight_is_not_a_fright(read):
    (g,) = read("museum", "As soon as the robot appears, a small boy squeals with delight.").groups
    assert g.robot_interaction != "avoid"
