"""A place phrase followed by "and" and a counted group ("beside the lifts and two cleaners in the ladies'",
"on the platform and two porters in the cafe"): "and two" does not run on into a numbered name ("lift 2",
"platform 2"), so the place before it is read and its people placed there. A name with "and" in it ("the
lost and found") is still read whole. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, location", [
    ("hospital", "Put a porter with a wheelchair beside the lifts and two cleaners in the ladies'.", "elevator_hall"),
    ("station", "Put a guard on the platform and two porters in the cafe.", "platform_1"),
    ("office", "Put a manager in the meeting room and two interns in the kitchen.", "boardroom"),
])
def test_the_place_before_and_a_count_is_read(read, world, prompt, location):
    groups = read(world, prompt).groups
    assert len(groups) == 2
    assert groups[0].location == location


def test_a_name_with_and_is_read_whole(read):
    assert read("market_hall", "A man walks to the lost and found.").groups[0].destination == "lost_property_shelves"
