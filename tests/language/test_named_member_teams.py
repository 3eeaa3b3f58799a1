"""A pair or team named by the people in it (paired_kin.py: "a husband-wife team", "a father-and-son duo", "two
mother-daughter teams") has as many people each as its name lists, not a team's usual size."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count", [
    ("hospital", "A husband-wife team of volunteers hand out tea in the waiting room.", 2),
    ("restaurant", "A husband and wife team wait by the bar.", 2),
    ("mall", "Two father-son teams head to the cinema.", 4),
    ("library", "A mother-and-daughter duo browse the shelves.", 2),
    ("station", "Three husband-and-wife teams wait on platform 1.", 6),
])
def test_name_lists_the_members(read, world, prompt, count):
    (group,) = read(world, prompt).groups
    assert group.count.value == count


@pytest.mark.parametrize("world,prompt,low", [
    ("hospital", "The security team patrol the corridors.", 3),
    ("office", "A team of cleaners mop the kitchen.", 3),
])
def test_plain_teams_keep_their_size(read, world, prompt, low):
    (group,) = read(world, prompt).groups
    assert group.count.low == low and group.count.high > low
