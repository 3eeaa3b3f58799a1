"""Surrounding or crowding round the robot so that it cannot pass is blocking it, even with where
they are between ("surround the robot in the lobby so that it cannot move"); surrounding it alone,
or to see it better, stays coming over to it (language/hemmed_in.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("office", "Four interns surround the robot in the lobby so that it cannot move."),
    ("mall", "A gang of teenagers surrounds the robot by the fountain so it cannot get through."),
    ("airport", "Three travellers crowd round the robot at check-in so the robot can't get by."),
])
def test_surrounding_the_robot_so_it_cannot_pass_blocks_it(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.robot_interaction, g.robot_reaction) == ("robot", "block", "Threatening")


@pytest.mark.parametrize("world,prompt", [
    ("mall", "A gang of teenagers surround the robot."),
    ("museum", "Kids crowd round the robot in the main hall so they can see it better."),
])
def test_surrounding_the_robot_alone_approaches_it(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.robot_interaction == "approach"
