"""The weather ("against the cold", "from the rain", "out of the wind") is no place: nothing is refused for
it, and where the people are is still read. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, location", [
    ("station", "Three commuters shelter from the rain in the waiting room.", "waiting_room"),
    ("mall", "A couple of smokers huddle out of the wind by the entrance.", "south_entrance_hall"),
    ("museum", "Two guards stamp their feet against the cold in the entrance hall.", "entrance_hall"),
    ("stadium", "The tea bar has a handful of away fans standing around it at half-time, stamping their feet "
                "against the cold.", "tea_bar"),
])
def test_the_weather_is_no_place(read, world, prompt, location):
    reading = read(world, prompt)
    assert reading.unknown_places == ()
    assert reading.groups[0].location == location
