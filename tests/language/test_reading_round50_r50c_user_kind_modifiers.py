"""Round 50 (r50c): a word before a place's head that names the kind of people it is for ("staff",
"crew", "members'") must agree with the place: a world without such a place refuses it rather than read
another place that shares the head (user_kinds.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,unknown", [
    ("mall", "A cleaner heads to the staff entrance.", "staff entrance"),
    ("airport", "Two pilots walk to the crew room.", "crew room"),
])
def test_a_place_for_a_kind_of_user_the_world_lacks_is_unknown(read, world, prompt, unknown):
    reading = read(world, prompt)
    assert reading.groups[0].destination is None
    assert unknown in reading.unknown_places


@pytest.mark.parametrize("world,prompt,destination", [
    ("museum", "A guard walks to the staff entrance.", "staff_entrance"),
    ("hospital", "A nurse walks to the staff room.", "staff_room"),
])
def test_a_place_for_a_kind_of_user_the_world_has_is_read(read, world, prompt, destination):
    assert read(world, prompt).groups[0].destination == destination
