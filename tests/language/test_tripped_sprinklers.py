"""Sprinklers said to trip ("the sprinklers trip", "the sprinkler system tripped") are a hazard like
sprinklers going off: people who leave after it evacuate (language/hazard_events.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("cinema", "Halfway through the film the sprinklers tripped, and the audience in screen one filed out to the car park."),
    ("hospital", "The sprinklers trip in the lobby and the staff head out of the building."),
    ("museum", "As soon as the sprinkler system trips, a school party in the cafe troops out through the entrance hall."),
])
def test_people_leaving_after_the_sprinklers_trip_evacuate(read, world, prompt):
    reading = read(world, prompt)
    assert [g.intent for g in reading.groups] == ["evacuate"]
