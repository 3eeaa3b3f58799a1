"""Leaving a place and then settling somewhere is going there (issue 29): a walk from the place left to
where they sit or slump, not a wait. Settling alone keeps its wait. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, goal", [
    ("hospital", "Two nurses leave the ward and sit down at the nurses station.", "ward_a", "nurse_station"),
    ("residential", "My roommate walks out of the restroom and sits on the couch.", "bathroom", "sofa"),
    ("residential", "My roommate heads out of the restroom and flops onto the couch to watch TV.", "bathroom", "sofa"),
])
def test_settling_after_leaving_a_place_is_going_there(read, world, prompt, start, goal):
    group = read(world, prompt).groups[0]
    assert group.intent == "walk"
    assert (group.start, group.destination) == (start, goal)


def test_settling_alone_is_still_a_wait(read):
    group = read("residential", "My roommate flops onto the couch.").groups[0]
    assert (group.intent, group.location) == ("wait", "sofa")
