"""A person-shaped place after "by" with no passive before it ("hover by the concierge", "wait by the
cashier"): where a group stays, no passive's doer and no second group. What the robot carries, or
where it carries it from ("linen from housekeeping"), is no group either."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("casino", "The robot hauls a crate of chips from the bar to the poker room while two gamblers linger by the cashier."),
    ("high_street_bank", "Three pensioners hover by the tellers while the robot rolls across to the entrance."),
    ("hotel", "The robot carries a pile of fresh towels from housekeeping to the spa as four guests wait by the concierge."),
])
def test_a_place_after_by_is_no_second_group(read, world, prompt):
    groups = read(world, prompt).groups
    assert len(groups) == 1, groups
    assert groups[0].location is not None, groups[0]


def test_a_passive_s_doer_is_still_a_group(read):
    groups = read("hotel", "The lobby is crossed by two porters.").groups
    assert len(groups) == 1 and groups[0].count.value == 2, groups
