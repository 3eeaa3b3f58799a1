"""Things gathered at one place and dropped or handed out at another (issue 29): the person goes from
the first place to the second. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, goal", [
    ("mall", "A cleaner grabs a stack of trays from the food court and leaves them by the cinema.",
     "food_court", "cinema_lobby"),
    ("office", "The intern picks up the printouts from the printer and hands them out in the boardroom.",
     "printer", "boardroom"),
])
def test_gathering_at_one_place_and_dropping_at_another_is_a_walk(read, world, prompt, start, goal):
    group = read(world, prompt).groups[0]
    assert group.intent == "walk"
    assert (group.start, group.destination) == (start, goal)


def test_gathering_alone_is_no_walk(read):
    group = read("office", "The intern picks up the printouts from the printer.").groups[0]
    assert group.destination is None
