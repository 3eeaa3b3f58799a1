"""The robot's name mistyped by one slip (language/robot_typos.py): letters swapped ("robto", "rboot",
"roobt"), one doubled ("robbot") or dropped, "teh" before it; it is still the robot, and a real word
one slip away ("root") is kept."""

from __future__ import annotations

import pytest

from grove_tui.language.robot_typos import with_robot_spelt


@pytest.mark.parametrize("world,prompt,interaction", [
    ("office", "Frightened of the robto, two interns duck behind the printer.", "avoid"),
    ("hospital", "Wary of the rboot, a porter waits in the corridor.", "avoid"),
    ("office", "An intern waves at the robbot from the kitchen.", "look"),
    ("museum", "A nervous visitor steps aside for the roobt in the entrance hall.", "avoid"),
])
def test_a_misspelt_robot_is_the_robot(read, world, prompt, interaction):
    groups = read(world, prompt).groups
    assert len(groups) == 1 and groups[0].intent == "robot"
    assert groups[0].robot_interaction == interaction


def test_teh_robot_is_the_robot_and_its_clause_is_read(read):
    reading = read("office", "teh robot waits by the printer while an intern makes tea")
    assert reading.robot is not None and (reading.robot.task, reading.robot.location) == ("wait", "printer")


@pytest.mark.parametrize("typed,written", [
    ("the robto", "the robot"), ("The Rbot waits", "The robot waits"), ("teh robot", "the robot"),
    ("two roobts", "two robots"), ("the roots of it", "the roots of it"), ("Robin walks", "Robin walks"),
    ("a root canal", "a root canal"),
])
def test_only_one_slip_from_the_robot_is_the_robot(typed, written):
    assert with_robot_spelt(typed).lower() == written.lower()
