"""One thing the world lacks is not a place the world names in the plural (plural_names): "the
supermarket" is not "the shops" of an outlet village's avenue."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, refused", [
    ("outlet_village", "A couple drift over to the supermarket.", "supermarket"),
    ("outlet_village", "An elderly pair shove an empty trolley over from the car park in the direction of the supermarket.",
     "supermarket"),
    ("outlet_village", "Two pensioners amble across towards the hypermarket.", "hypermarket"),
])
def test_singular_kind_is_refused(read, world, prompt, refused):
    r = read(world, prompt)
    assert r.unknown_places == (refused,)
    assert r.groups[0].destination is None


def test_the_plural_name_itself_is_still_read(read):
    assert read("outlet_village", "Two shoppers walk over to the shops.").groups[0].destination == "avenue"
