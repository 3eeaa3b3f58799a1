"""Round 58 (r58c): a participle of paying or buying right after the place is the group's purpose
("queue at the pharmacy collecting prescriptions", "wait at the reception desk, paying for parking"),
not after a person ("a man buying coffee walks ...") (language/paying_purposes.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,place,purpose", [
    ("hospital", "Four visitors queue at the pharmacy collecting prescriptions.", "pharmacy", "prescriptions"),
    ("hospital", "Three patients wait at the reception desk, paying for parking.", "reception_desk", "parking"),
    ("golf_club", "Twelve golfers queue at the pro's till paying green fees.", "shop_counter", "fees"),
])
def test_paying_after_the_place_is_the_purpose(read, world, prompt, place, purpose):
    group = read(world, prompt).groups[0]
    assert group.location == place
    assert group.purpose is not None and purpose in group.purpose


def test_buying_after_a_person_is_no_purpose(read):
    assert read("hospital", "A man buying coffee walks to the exit.").groups[0].purpose is None
