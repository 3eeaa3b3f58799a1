"""A kind of room said by an "-ing" word before a word for rooms ("the old changing rooms", "the drying
room"): the "-ing" word is no verb ending the phrase, and it says which kind of room, so a world
without one refuses it rather than taking any room ("the staff room"). A world with one reads it, and
a synonym ("the eating area") still finds its place. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt", [
    ("primary_school", "Four volunteers in hi-vis stroll across from the staffroom to the old changing rooms."),
    ("garden_centre", "Two staff walk from the cafe to the changing rooms."),
    ("community_centre", "Two volunteers walk from the kitchen to the old changing rooms."),
])
def test_a_kind_of_room_the_world_lacks_is_refused(read, world, prompt):
    assert any("changing room" in u for u in read(world, prompt).unknown_places)


@pytest.mark.parametrize("world, prompt, destination", [
    ("climbing_centre", "Two climbers walk from the cafe to the changing rooms.", "changing_rooms"),
    ("hospital", "Two visitors walk to the eating area.", "cafeteria"),
    ("hospital", "Two nurses walk to the waiting room.", "main_waiting_room"),
])
def test_a_kind_of_room_the_world_has_is_read(read, world, prompt, destination):
    assert read(world, prompt).groups[0].destination == destination
