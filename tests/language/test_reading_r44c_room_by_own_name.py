"""A room said by its own name wins over a fixture inside it that has the same words as an alias: "the
phone booths" of a coworking space is the phone booth area, not one of its pods ("phone booth"); "the
showers" of a fire station is the shower room, not its cubicles ("shower"). A fixture said by its own
name is still the fixture. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, destination", [
    ("coworking_space", "Of the 12 meetup attendees in the event space, 4 duck into the phone booths for calls.",
     "phone_booths"),
    ("coworking_space", "Two freelancers hurry from the hot desks to the phone booths.", "phone_booths"),
    ("fire_station", "After the drill two firefighters head from the drill yard to the showers.", "showers"),
])
def test_a_room_by_its_own_name(read, world, prompt, destination):
    groups = read(world, prompt).groups
    assert groups[-1].destination == destination


@pytest.mark.parametrize("world, prompt, location", [
    ("fire_station", "A firefighter stands in a shower cubicle.", "shower_cubicles"),
    ("coworking_space", "A member takes a call in a phone pod.", "phone_pods"),
])
def test_a_fixture_by_its_own_name(read, world, prompt, location):
    assert read(world, prompt).groups[0].location == location
