"""Round 44: a stay said as a noun with its length as a hyphened adjective ("After a fifteen-minute wait in
the waiting room, a teenager heads for the exit") is a stay where they are before they go, as "After
fifteen minutes in the waiting room" is."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,seconds,start,destination", [
    ("hospital", "After a fifteen-minute wait in the main waiting room, a teenager heads for the main entrance.", 900,
     "main_waiting_room", "main_entrance"),
    ("hospital", "Following a 20-minute break in the staff room, two nurses go back to ward A.", 1200, "staff_room",
     "ward_a"),
    ("airport", "After a half-hour wait at gate A1, a family of four walks to the café.", 1800, None, "cafe"),
])
def test_a_hyphened_length_of_a_stay_is_a_wait_first(read, world, prompt, seconds, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.wait_seconds, g.destination) == ("walk", seconds, destination)
    assert start is None or g.start == start


def test_a_hyphened_length_of_a_thing_is_no_stay(read):
    (g,) = read("office", "A courier with a two-minute delivery slot walks to reception.").groups
    assert g.wait_seconds is None
