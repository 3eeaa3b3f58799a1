"""A list of people each placed on their own, whose last item is a pair with a participle ("3 check-in
agents @ info desk, pilot + co-pilot walking to B1", "three nurses at the nurses' station, a porter and a
doctor heading to ward B"): the participle is the pair's, so the people before stay where they are
said to be. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, location, destination", [
    ("airport", "3 check-in agents @ info desk, pilot + co-pilot walking to B1", "information_desk", "gate_b1"),
    ("cinema", "2 ushers @ the kiosk, manager + projectionist walking to screen 3", "ticket_kiosks", "screen_3"),
    ("hospital", "Three nurses at the nurses' station, a porter and a doctor heading to ward B.", "nurse_station", "ward_b"),
    ("station", "A guard on platform 1, a cleaner and a porter walking to the cafe.", "platform_1", "cafe"),
])
def test_the_pairs_participle_is_its_own(read, world, prompt, location, destination):
    groups = read(world, prompt).groups
    assert (groups[0].intent, groups[0].location, groups[0].destination) == ("wait", location, None)
    assert all(g.destination == destination for g in groups[1:])
