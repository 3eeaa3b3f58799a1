"""An informal name read as a fixture its room fits as well is the room: "the loo" is read as "toilet",
both the name of the house's toilet and an alias of its bathroom, and people go to or come from the
room. A fixture said by its own name ("sits on the toilet") stays the fixture. Only the residential
world has a toilet fixture inside a room aliased "toilet", so the class is checked there. Real spaCy."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("prompt, role", [
    ("Nana steers our drowsy youngest from the loo to his own little bedroom.", "start"),
    ("Grandad shuffles from the living room to the loo.", "destination"),
    ("The twins race each other from the bog to the kitchen.", "start"),
])
def test_the_loo_is_the_bathroom(read, prompt, role):
    assert getattr(read("residential", prompt).groups[0], role) == "bathroom"


def test_the_toilet_sat_on_is_the_fixture(read):
    assert read("residential", "The toddler sits on the toilet.").groups[0].location == "toilet"
