"""First names joined as one subject are one person each (joined_names.py): "Alice and Bob walk to the
kitchen" was a vague crowd of six, since only a lone name had its verb."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,names,place", [
    ("office", "Marek and Joanna stroll from reception to the kitchen.", ["marek", "joanna"], "kitchen"),
    ("hospital", "At noon, Nadia, Kofi and Ingrid head to the cafeteria.", ["nadia", "kofi", "ingrid"], "cafeteria"),
    ("library", "Yusuf and Grete from the book club walk over to the café.", ["yusuf", "grete"], None),
    ("mall", "While Hamid and Lotte queue at the food court, the robot patrols the atrium.", ["hamid", "lotte"], "food_court"),
])
def test_each_joined_name_is_one_person(read, world, prompt, names, place):
    groups = read(world, prompt).groups
    assert [g.label for g in groups] == names
    assert all(g.count.value == 1 for g in groups)
    if place is not None:
        assert all(place in (g.destination, g.location) for g in groups)


def test_a_shop_named_by_two_names_is_no_one(read):
    (group,) = read("mall", "A courier carries a parcel from Hobbs and Jenner to the food court.").groups
    assert group.label == "courier"
