"""A thing left with a desk or at a counter is taken there: "leaves a box with the community desk" is no
box to refuse and no start at a desk, but a trip to the desk; when the sentence goes on to another trip,
the desk is where that one starts. A place left ("leaves the cafeteria") is still left. Real spaCy, real
worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, destination", [
    ("coworking_space", "A courier leaves a box with the community desk, not on the post shelf.", "front_desk"),
    ("coworking_space", "A courier leaves a parcel at the community desk.", "front_desk"),
    ("hotel", "A delivery driver leaves a crate of flowers at the front desk.", "reception_desk"),
    ("museum", "A schoolteacher leaves a pile of coats with the cloakroom.", "cloakroom"),
])
def test_a_thing_left_somewhere_is_taken_there(read, world, prompt, destination):
    reading = read(world, prompt)
    assert reading.unknown_places == ()
    assert reading.groups[0].destination == destination


@pytest.mark.parametrize("world, prompt, start, destination", [
    ("hotel", "A guest leaves her key at the front desk and walks to the bar.", "reception_desk", "bar"),
    ("museum", "A tourist leaves his rucksack with the cloakroom and heads into the great hall.", "cloakroom", "great_hall"),
])
def test_a_thing_left_on_the_way_starts_the_next_trip(read, world, prompt, start, destination):
    group = read(world, prompt).groups[0]
    assert (group.start, group.destination) == (start, destination)


def test_a_place_left_is_still_left(read):
    assert read("hospital", "A visitor leaves the cafeteria at noon.").groups[0].start == "cafeteria"
