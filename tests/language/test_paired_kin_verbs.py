"""One pair named by two people, with the verb said for two ("a mother and daughter team run the stall"):
one duo of two, doing what the verb says there (paired_kin.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,place", [
    ("mall", "A father and son team staff the phone repair kiosk by the fountain.", None),
    ("station", "A husband and wife team run the coffee cart on the concourse.", "concourse"),
])
def test_a_pair_with_a_plural_verb_is_two(read, world, prompt, place):
    (group,) = read(world, prompt).groups
    assert group.count.value == 2
    if place is not None:
        assert group.location == place
