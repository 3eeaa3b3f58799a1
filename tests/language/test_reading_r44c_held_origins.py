"""Where a thing held came from ("clutching mugs from the seconds shelf", "clutching sandwiches from the
deli", "cradling a bonsai from the bonsai nursery") is no place the people are at or go to, so a world
without it refuses nothing; a thing carried along a route still starts where it is carried from.
Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, location", [
    ("pottery_studio", "Half a dozen customers are lined up at the till clutching mugs from the seconds shelf.", "shop_till"),
    ("station", "Two students wait on platform 2 clutching sandwiches from the deli.", "platform_2"),
    ("garden_centre", "A man queues at the tills cradling a bonsai from the bonsai nursery.", "tills"),
])
def test_where_a_held_thing_came_from_is_not_refused(read, world, prompt, location):
    reading = read(world, prompt)
    assert reading.unknown_places == ()
    assert reading.groups[0].location == location


def test_a_carried_things_start_the_world_lacks_is_still_refused(read):
    assert "loading bay" in read("hospital", "A porter carries boxes from the loading bay to the pharmacy.").unknown_places
