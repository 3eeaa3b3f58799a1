"""A purpose that is a service done to a thing of one's own ("to get his prescription filled", "to get her
passport photo checked"): done where the room serves people in turn, its one queue-and-service fixture,
though a kiosk of that room is described with the same thing. A purpose of handing a thing in stays at
the place for it. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, destination", [
    ("hospital", "An old man walks from the lobby to get his prescription filled.", "pharmacy_counter"),
    ("hospital", "A pensioner shuffles over from the cafeteria to have her prescription filled.", "pharmacy_counter"),
    ("post_office", "A woman walks in to get her passport photo checked.", "post_office_counter"),
])
def test_a_service_is_done_at_the_rooms_service_point(read, world, prompt, destination):
    assert read(world, prompt).groups[0].destination == destination


def test_handing_a_thing_in_stays_at_its_place(read):
    group = read("hospital", "A woman walks from the lobby to hand in her prescription.").groups[0]
    assert group.destination == "prescription_dropoff"
