"""People "outside" a room set against another group already in the zone outside it: they are at that
room, not in the same zone as the first group ("Two kids sit on the concourse benches while their dad
waits outside the newsagent"). Alone, "outside X" stays the zone X's door opens to. Real spaCy, real
worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, first, second", [
    ("station", "Two kids sit on the concourse benches while their dad waits outside the newsagent.",
     "concourse_benches", "newsagent"),
    ("mall", "Ten teens hang around in the east mall and four more loiter outside the cinema.",
     "east_mall", "cinema_lobby"),
])
def test_outside_set_against_the_zone_outside_is_the_room(read, world, prompt, first, second):
    groups = read(world, prompt).groups
    assert [g.location for g in groups] == [first, second]


@pytest.mark.parametrize("world, prompt, location", [
    ("station", "A man waits outside the newsagent.", "concourse"),
    ("station", "Six delegates wait in the concourse outside the newsagent.", "concourse"),
    ("mall", "Four teenagers loiter outside the cinema.", "east_mall"),
])
def test_outside_alone_is_still_the_zone_outside(read, world, prompt, location):
    assert read(world, prompt).groups[0].location == location
