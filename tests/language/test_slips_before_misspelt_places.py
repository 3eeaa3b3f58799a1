""""form" for "from" before a misspelt place (issue 29): two slips in one sentence ("hurries form the
cafetria to the pharmacy") still read as a route from the misspelt place. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, goal", [
    ("hospital", "the nurse hurries form the cafetria to the pharmacy", "cafeteria", "pharmacy"),
    ("mall", "two girls wander form the cinma to the food court", "cinema_lobby", "food_court"),
])
def test_form_before_a_misspelt_place_is_from(read, world, prompt, start, goal):
    group = read(world, prompt).groups[0]
    assert group.intent == "walk"
    assert (group.start, group.destination) == (start, goal)


def test_a_line_formed_is_no_route(read):
    group = read("hospital", "three visitors form a line at the cafetria").groups[0]
    assert group.start is None
