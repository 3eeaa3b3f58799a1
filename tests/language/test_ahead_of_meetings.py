"""A workplace's short meeting said with "ahead of" after where people go (issue 29): "ahead of the nine
o'clock huddle", "ahead of the morning handover" is why they go there, their purpose. Real spaCy, real
worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, goal, event", [
    ("hospital", "Two doctors hurry to the nurses station ahead of the morning handover.", "nurse_station", "handover"),
    ("office", "Three developers head to the meeting room ahead of the ten o'clock stand-up.", "boardroom", "stand-up"),
    ("call_centre", "Gareth Pryce comes out of his office and makes for the huddle board ahead of the nine o'clock "
     "huddle.", "huddle_board", "huddle"),
])
def test_a_meeting_said_with_ahead_of_is_the_purpose(read, world, prompt, goal, event):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.destination) == ("walk", goal)
    assert group.purpose is not None and event in group.purpose
