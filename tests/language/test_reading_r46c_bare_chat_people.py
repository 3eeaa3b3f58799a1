"""Round 46: a chat list's item that is a bare person of two words ("new starter @ X") or an adjective
in "-ed" and a person ("tired manager @ X", "worried relative by X") is a person of its own, as with "a"."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, people", [
    ("hospital", "3 nurses at pharmacy, worried relative by the lifts, robot ward b -> ICU", [3, 1]),
    ("station", "2 guards @ gateline, lost tourist nr ticket machines, bot on patrol", [2, 1]),
    ("office", "2 devs in the kitchen, new hire @ reception, robot reception -> kitchen", [2, 1]),
    ("supermarket", "4 shoppers at the checkouts, stressed manager by the entrance", [4, 1]),
])
def test_a_bare_described_person_is_an_item(read, world, prompt, people):
    reading = read(world, prompt)
    assert [g.count.value for g in reading.groups] == people
    assert all(g.location is not None for g in reading.groups)
