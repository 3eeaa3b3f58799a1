"""A word the world names places by with a number it lacks, after "for" ("leaves the pharmacy for ward
7" where the wards are lettered), is a place to refuse, never a purpose (numbered_names.numbered_kind).
A number the world has is still where they go."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,refused", [
    ("hospital", "A nurse leaves the pharmacy for ward 7.", "ward 7"),
    ("hospital", "Two porters set off from the lobby for ward 9.", "ward 9"),
    ("airport", "Four passengers leave the cafe for gate 99.", "gate 99"),
    ("station", "Two commuters leave the cafe for platform 12.", "platform 12"),
])
def test_a_number_the_world_lacks_is_refused(read, world, prompt, refused):
    r = read(world, prompt)
    assert refused in r.unknown_places
    (g,) = r.groups
    assert g.purpose is None


def test_a_number_the_world_has_is_the_destination(read):
    (g,) = read("station", "Two commuters leave the cafe for platform 2.").groups
    assert g.destination == "platform_2"
    (g,) = read("hospital", "A nurse leaves the pharmacy for ward B.").groups
    assert g.destination == "ward_b"
