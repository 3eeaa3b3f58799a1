"""A posture between a verb of going and the robot it goes after or towards ("crawls on all fours after
the robot", "creeps on tiptoe behind it") says only how they go: following or going up to the robot."""

from __future__ import annotations

import pytest

from grove_tui.language.posture_manners import without_posture_before_going
from grove_tui.language.reading import read_prompt


@pytest.mark.parametrize("world,prompt,interaction", [
    ("mall", "Fascinated, a toddler crawls on all fours after the robot.", "follow"),
    ("mall", "Two giggling girls creep on tiptoe behind the robot past the fountain.", "follow"),
    ("museum", "Entranced, a baby crawls on her hands and knees towards the robot.", "approach"),
    ("hospital", "A little boy scoots on his bottom after the robot.", "follow"),
])
def test_a_posture_before_after_or_towards_the_robot(worlds, world, prompt, interaction):
    group = read_prompt(prompt, worlds[world]).groups[0]
    assert group.intent == "robot" and group.robot_interaction == interaction, group


def test_a_posture_elsewhere_is_kept():
    text = "A gardener kneels on his knees in the flower bed."
    assert without_posture_before_going(text) == text
