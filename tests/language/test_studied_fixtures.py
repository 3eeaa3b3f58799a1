"""People who study, photograph or film a fixture of the world are at it, as those who examine it are
("of the nine tourists filming the fountain, three drift off": the rest stay at the fountain); the same
verbs with the robot for their object are still a reaction to it."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt


@pytest.mark.parametrize("world,prompt,place", [
    ("museum", "Eighteen engineers are photographing the mummy case.", "mummy_case"),
    ("mall", "Of the nine tourists filming the fountain, three drift off to the toy shop.", "fountain"),
    ("museum", "Of the ten pupils studying the mummy case, four drift off to the gift shop.", "mummy_case"),
])
def test_people_studying_a_fixture_are_at_it(worlds, world, prompt, place):
    group = read_prompt(prompt, worlds[world]).groups[0]
    assert group.location == place, group


def test_photographing_the_robot_is_still_looking_at_it(worlds):
    group = read_prompt("A girl photographs the robot in the great hall.", worlds["museum"]).groups[0]
    assert group.intent == "robot" and group.robot_interaction == "look", group
