"""A way out of the building said last, along or down which people go with nowhere else to go ("trail
out of the departure lounge and down the forward gangway", "file out of the gate area and along the jet
bridge"), is where they end, not a place passed. A corridor inside stays a way through. Real spaCy,
real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, destination", [
    ("ferry_terminal", "Sixty-odd hikers with rucksacks trail out of the departure lounge and down the forward gangway.",
     "departure_lounge", "gangway_1"),
    ("ferry_terminal", "A family walks from the boarding area down the aft gangway.", "boarding_area", "gangway_2"),
    ("airport", "Passengers file out of the gate area and along the jet bridge.", "concourse", "gate_a1_jet_bridge"),
])
def test_a_way_out_said_last_is_where_they_end(read, world, prompt, start, destination):
    group = read(world, prompt).groups[0]
    assert (group.start, group.destination) == (start, destination)


def test_a_corridor_inside_is_still_a_way_through(read):
    group = read("hospital", "A porter walks from the lobby through the corridor.").groups[0]
    assert group.destination is None and group.via == ("main_corridor",)
