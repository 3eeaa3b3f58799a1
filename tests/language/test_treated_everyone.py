"""Round 70 (r70a): "everyone" whom a purpose treats ("to buy everybody some sandwiches", "to fetch us
all a coffee") is no group in the scene (language/treated_everyone.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,place", [
    ("hospital", "A porter nips down to the cafeteria to buy everybody some sandwiches.", "cafeteria"),
    ("hospital", "The ward clerk heads to the pharmacy to fetch us all a coffee.", "pharmacy"),
    ("office", "After lunch the intern slips into the kitchen to get everyone a cake.", "kitchen"),
])
def test_everyone_a_purpose_treats_is_no_group(read, world, prompt, place):
    (group,) = read(world, prompt).groups
    assert group.count.value == 1 and group.destination == place
