"""Round 46 (r46a): a fronted stay's place is where the walk starts, a seat or a counter as much as a room
("After half an hour on the benches, two students walk to ..."): the thing itself, not the room around it
(fronted_stays.stayed_spots, roles.py). An evacuation still starts from the room."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start", [
    ("bus_station", "After half an hour on the benches, two students walk to the exit.", "waiting_benches"),
    ("hospital", "After twenty minutes at the pharmacy counter, an old man shuffles to the exit.", "pharmacy_counter"),
])
def test_a_fronted_stays_place_is_the_start(read, world, prompt, start):
    (group,) = read(world, prompt).groups
    assert (group.intent, group.start) == ("walk", start)


def test_an_evacuation_after_a_fronted_stay_starts_from_the_room(read):
    (group,) = read("bus_station", "After half an hour on the benches, two students hear the fire alarm and leave.").groups
    assert (group.intent, group.start) == ("evacuate", "waiting_room")
