"""Ignoring the robot is no reaction to it (language/reactions.py): "gather round the coffee machine,
ignoring the robot" is not gathering round the robot."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

IGNORED = [
    ("office", "Three interns gather round the coffee machine, ignoring the robot.", "coffee_machine"),
    ("museum", "A crowd of visitors gathers round the dinosaur skeleton, ignoring the robot.", "t_rex_skeleton"),
    ("station", "Four commuters huddle round the departure board and ignore the robot completely.", "departure_board"),
]


@pytest.mark.parametrize("world, sentence, location", IGNORED)
def test_people_who_ignore_the_robot_do_not_react_to_it(world, sentence, location):
    group = read_prompt(sentence, load_world(world)).groups[0]
    assert group.robot_interaction is None and group.intent != "robot"
    assert group.location == location


@pytest.mark.parametrize("world, sentence, interaction", [
    ("office", "A manager ignores the queue and walks up to the robot.", "approach"),
    ("museum", "Visitors gather round the robot.", "approach"),
])
def test_ignoring_something_else_keeps_the_reaction(world, sentence, interaction):
    assert read_prompt(sentence, load_world(world)).groups[0].robot_interaction == interaction
