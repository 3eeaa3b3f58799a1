"""A time said part-way through an event with no comma before the subject ("Halfway through the quiz
smoke pours ..."): the event ends the time, so nothing of it is refused as a place (held_and_spans.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("concert_venue", "Halfway through the gig smoke pours from the backstage and forty fans leave by the main doors."),
    ("community_centre", "Midway through the quiz night a fire starts in the kitchen and thirty people leave by the main entrance."),
    ("cruise_ship", "Partway through the film popcorn spills and twelve passengers walk to the embarkation lounge."),
])
def test_a_time_running_into_the_subject_is_no_place(read, world, prompt):
    r = read(world, prompt)
    assert r.unknown_places == ()
    assert r.groups


def test_a_room_after_halfway_through_is_still_a_place(read):
    r = read("mall", "Two guards walk halfway through the food court.")
    assert r.unknown_places == ()
