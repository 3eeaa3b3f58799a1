"""A child carried with a describing word before "little" is still a second group that follows
(language/described_youngest.py); a councillor the robot shows the way is one person who follows it
(the lexicon's person nouns)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt", [
    ("mall", "A mum carries her drowsy wee son from the lifts to the food court."),
    ("museum", "A grandad carries his drowsy little granddaughter from the cafe to the gift shop."),
])
def test_a_described_little_child_carried_follows(read, world, prompt):
    groups = read(world, prompt).groups
    assert len(groups) == 2 and groups[1].intent == "follow"


@pytest.mark.parametrize("world, prompt", [
    ("office", "The robot shows a local councillor the way from reception to the meeting room."),
    ("station", "The robot shows a councillor the way to platform 2."),
])
def test_a_councillor_shown_the_way_follows_the_robot(read, world, prompt):
    g = read(world, prompt).groups[0]
    assert (g.count.value, g.robot_interaction) == (1, "follow")
