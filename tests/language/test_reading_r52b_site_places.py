"""A car park is a place of a site a world may lack: going across to it with no leaving said and no
hazard refuses it; going out to it is leaving by the nearest exit; the street is always past the
doors. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt", [
    ("museum", "Two guards stroll from the great hall over to the car park."),
    ("library", "A librarian walks from the reading room across to the car park."),
])
def test_a_car_park_the_world_lacks_is_refused(read, world, prompt):
    assert read(world, prompt).unknown_places == ("car park",)


@pytest.mark.parametrize("world, prompt", [
    ("museum", "Two guards walk out of the great hall to the car park."),
    ("library", "Smoke fills the reading room and the readers hurry to the car park."),
    ("museum", "Three visitors go from the great hall to the street."),
])
def test_going_out_to_the_outdoors_is_no_refusal(read, world, prompt):
    reading = read(world, prompt)
    assert reading.unknown_places == ()
    assert reading.groups[0].destination is not None
