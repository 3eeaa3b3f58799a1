"""What people wear or carry, said as a bare plural after "in" that a fixture of the world is named
after: "Cub Scouts in grip socks" (the grip sock machine), "recruits in BA sets" (the BA set rack),
"technicians in bunny suits" (the gown rack). It is no place they are in, so it does not outrank the
room they set off from. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start", [
    ("trampoline_park", "Three Cub Scouts in grip socks set off from the locker room for the foam pit.", "locker_room"),
    ("fire_station", "Two recruits in BA sets jog from the kit room out to the smoke house in the drill yard.", "kit_room"),
    ("research_lab_building", "Two technicians in bunny suits leave the gowning room for the clean room.", "gowning_room"),
    ("ice_rink", "Three kids in skate aids shuffle from the skate hire to the rink.", "skate_hire"),
])
def test_a_worn_fixture_is_no_start(read, world, prompt, start):
    assert read(world, prompt).groups[0].start == start


def test_a_room_said_bare_after_in_is_still_a_place(read):
    group = read("hospital", "Two nurses in ward B walk to the pharmacy.").groups[0]
    assert group.start == "ward_b"


def test_party_hats_are_worn_not_refused(read):
    prompt = "The birthday crowd, nine cub scouts in party hats, are tucking into pizza at the long tables in Pole Position."
    reading = read("karting_centre", prompt)
    assert reading.unknown_places == ()
    assert reading.groups[0].location == "pole_position_tables"
