""""Spends three quarters of an hour at X before going to Y" is a wait at X, then the walk to Y: the
stay is read in quarters and in units and a half or a quarter more (counts.duration_at)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,place,destination,seconds", [
    ("hospital", "A visitor spends three quarters of an hour in the cafeteria before going to the main entrance.",
     "cafeteria", "main_entrance", 2700.0),
    ("museum", "Two students spend an hour and a half in the cafe before heading over to the entrance hall.",
     "cafe", "entrance_hall", 5400.0),
    ("museum", "A man spends an hour and a quarter in the cafe before going to the entrance hall.",
     "cafe", "entrance_hall", 4500.0),
])
def test_a_stay_in_quarters_then_the_walk(read, world, prompt, place, destination, seconds):
    (g,) = read(world, prompt).groups
    assert (g.start, g.destination, g.wait_seconds) == (place, destination, seconds)


def test_waiting_three_quarters_of_an_hour(read):
    (g,) = read("station", "A commuter waits in the ticket office for three quarters of an hour.").groups
    assert (g.location, g.wait_seconds) == ("ticket_office", 2700.0)
