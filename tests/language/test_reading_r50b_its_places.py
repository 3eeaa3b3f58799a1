"""Round 50 (r50b): "its X" after a room is that room's X (its_places.py): "the players in the indoor hall
are hurried out through its fire exit" is the hall's own fire exit, not the corridor's "fire exit"; "the
travellers on platform 2 are led out through its emergency exit" is platform 2's, though every platform has
one."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("tennis_club", "When the alarm sounds, the twelve players in the indoor hall are hurried out through its fire exit.",
     "indoor_courts", "indoor_fire_exit"),
    ("station", "The commuters waiting on platform 2 are led out through its emergency exit.",
     "platform_2", "platform_2_exit"),
    ("vaccination_centre", "The people in the waiting area are moved out through its fire exit.",
     "waiting_area", "waiting_fire_exit"),
])
def test_its_door_is_the_door_of_the_room_said_before(read, world, prompt, start, destination):
    (group,) = read(world, prompt).groups
    assert (group.start, group.destination) == (start, destination)
