"""Running off from the robot said with a bare "from" ("bolt from the robot", "flee from it") is keeping away
from it (language/robot_shrinking.py): these read as a plain walk with no reaction before. A verb of walking
"from" the robot's own things ("the robot bay", "the robot's dock") is where people start, no flight."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt


@pytest.mark.parametrize("world, prompt, destination", [
    ("mall", "Both toddlers bolt from the robot.", None),
    ("hospital", "A nurse bolts from the robot.", None),
    ("airport", "Terrified, three tourists flee from the robot toward the gates.", "gate_b1"),
    ("mall", "Two kids run from the robot to the fountain.", "fountain"),
    ("station", "Wailing, a toddler scarpers from the robot.", None),
    ("office", "Two interns dash from the robot into the kitchen.", "kitchen"),
])
def test_running_off_from_the_robot_keeps_away_from_it(worlds, world, prompt, destination):
    (g,) = read_prompt(prompt, worlds[world]).groups
    assert (g.intent, g.robot_interaction, g.robot_reaction) == ("robot", "avoid", "Scared"), g
    assert g.destination == destination


@pytest.mark.parametrize("world, prompt", [
    ("hospital", "A nurse hurries from the robot bay to ward A."),
    ("hospital", "A porter walks from the robot's dock to the pharmacy."),
    ("office", "An engineer runs from the robot lab to the kitchen."),
])
def test_from_the_robots_own_things_is_no_flight(worlds, world, prompt):
    (g,) = read_prompt(prompt, worlds[world]).groups
    assert g.robot_interaction is None and g.intent == "walk", g
