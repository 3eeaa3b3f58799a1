"""A room the world names by a first name ("Tom's room", "Priya's room") said as "his room" / "her room"
after that name owns someone else ("Tom's mum carries ... to his room"): the named person's room, not a
room of the mum's kind (language/possessor_rooms.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,destination", [
    ("hall_of_residence", "Tom's mum carries a box of books from reception to his room.", "bedroom_g02"),
    ("hall_of_residence", "Priya's dad walks from the common room to her room.", "bedroom_g01"),
    ("care_home", "Stan's daughter walks from the lounge to his room.", "room_2"),
])
def test_his_or_her_room_after_a_named_owner_is_that_person_s(read, world, prompt, destination):
    (g,) = read(world, prompt).groups
    assert g.destination == destination
