"""A clause that finds a room, said with a head that is the kind of one of its fixtures ("the counter that
does fried chicken", "the counter that does sausages"): the room's fixture of that kind, not the room.
Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, destination", [
    ("food_court", "Four lads step off the escalators and make for the counter that does fried chicken.", "chicken_counter"),
    ("market_hall", "A pensioner shuffles over to the counter that does sausages.", "butcher_counter"),
    ("food_court", "Two girls head for the counter that sells noodles.", "noodle_counter"),
])
def test_the_fixture_the_head_names(read, world, prompt, destination):
    assert read(world, prompt).groups[0].destination == destination


def test_a_room_said_by_a_word_for_rooms_stays_the_room(read):
    group = read("museum", "A class walks to the room where kids do crafts.").groups[0]
    assert group.destination == "education_room"
