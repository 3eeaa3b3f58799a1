"""A fronted feeling and a move away from the robot is fright, avoiding it; curiosity that walks over
to it approaches it (language/fronted_fright_moves.py). "our machine", "our cleaning bot" are the
robot (language/robot_aliases.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt", [
    ("mall", "Terrified, a toddler by the fountain hides behind her pushchair once our machine trundles past."),
    ("station", "Unnerved by the robot, a backpacker on platform 2 shuffles off sideways."),
    ("hospital", "Frazzled when it bleeps behind him, an old porter backs hastily away from our cleaning bot."),
    ("office", "Spooked by the robot turning the corner, an intern quickly backs off."),
])
def test_fronted_fright_moving_away_is_scared(read, world, prompt):
    g = read(world, prompt).groups[0]
    assert (g.robot_interaction, g.robot_reaction) == ("avoid", "Scared")


@pytest.mark.parametrize("world, prompt", [
    ("museum", "Intrigued, two teenagers leave the gift shop and amble over to inspect our machine."),
    ("airport", "Curious, a pilot strolls across to look at the robot."),
])
def test_fronted_curiosity_walking_over_approaches(read, world, prompt):
    g = read(world, prompt).groups[0]
    assert (g.robot_interaction, g.robot_reaction) == ("approach", "Curious")


def test_a_start_that_only_steps_back_stays_a_look(read):
    g = read("station", "Startled by the robot, a man at the ticket machines steps back.").groups[0]
    assert g.robot_interaction == "look"


def test_our_coffee_machine_is_not_the_robot(read):
    r = read("office", "Two clerks chat by our coffee machine.")
    assert all(g.robot_interaction is None for g in r.groups)
