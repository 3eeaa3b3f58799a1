"""A collective of people after a place preposition ("through a swarm of schoolkids", "through a gaggle of
pensioners", "a steady stream of commuters") is the people passed, no place the world lacks. Real spaCy,
real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt", [
    ("museum", "The robot weaves through a swarm of schoolkids milling under the whale skeleton, bound for the café."),
    ("city_farm", "The robot threads its way through a gaggle of pensioners feeding the goats, heading for the cafe."),
    ("station", "The robot edges through a steady stream of commuters on the concourse to the ticket office."),
    ("zoo", "A keeper pushes through a herd of teenagers at the penguin pool to the gift shop."),
])
def test_a_collective_of_people_is_no_place(read, world, prompt):
    assert read(world, prompt).unknown_places == ()


def test_a_room_after_through_is_still_refused(read):
    assert "ballroom" in read("museum", "The robot rolls through the ballroom to the café.").unknown_places
