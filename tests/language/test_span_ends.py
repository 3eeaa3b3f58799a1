"""The end or start of a span ("at the end of his session", "towards the close of visiting") is a time,
no place to refuse; the end of a room ("the end of the corridor", "the end of the day room") is a place.
Real spaCy, real worlds and the eval worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt", [
    ("hospital", "At the end of her shift a nurse walks from the ward to the main entrance."),
    ("hospital", "A porter wheels a patient from the ward to the main entrance towards the close of visiting."),
    ("office", "Two interns walk from reception to the kitchen at the start of their appointment."),
    ("gp_surgery", "By the end of the morning clinic a receptionist heads to the staff room."),
])
def test_the_part_of_a_span_is_no_place(read, world, prompt):
    reading = read(world, prompt)
    assert reading.unknown_places == ()
    assert reading.groups


def test_the_end_of_a_room_the_world_lacks_is_still_refused(read):
    assert read("hospital", "A nurse waits at the end of the day room.").unknown_places
