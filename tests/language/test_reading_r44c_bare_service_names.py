"""Places said without an article whose first word the parser takes for a verb: "walks to lost property",
"leaves the lounge for lost property", "over to left luggage". A world that has one reads it; a world
that lacks one refuses it, where before no place phrase was read at all. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt", [
    ("ferry_terminal", "A tearful backpacker walks from the departure lounge to lost property to ask about her passport."),
    ("bus_station", "A woman who left her umbrella on the X4 leaves the passenger lounge for lost property."),
    ("cinema", "A man hurries from the foyer to lost property."),
    ("library", "A student wanders from the study area over to left luggage."),
])
def test_a_service_the_world_lacks_is_refused(read, world, prompt):
    assert any(u.startswith(("lost", "left")) for u in read(world, prompt).unknown_places)


@pytest.mark.parametrize("world, prompt, destination", [
    ("market_hall", "A shopper walks from the market office to lost property.", "lost_property_shelves"),
    ("station", "A man strolls from the cafe to left luggage.", "left_luggage"),
    ("bus_station", "Two students leave the cafe for left luggage.", "left_luggage"),
])
def test_a_service_the_world_has_is_read(read, world, prompt, destination):
    reading = read(world, prompt)
    assert reading.unknown_places == ()
    assert reading.groups[0].destination == destination
