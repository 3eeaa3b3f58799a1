"""Round 56 (r56a): in a placing order ("Put ...", "Have ..."), a name or a kin word after "and" with a
place after it is one more person placed: "Put three visitors in the canteen and Tom at reception"
(language/placed_and_names.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,places", [
    ("hospital", "Put three visitors in the canteen and Tom at reception.", ["cafeteria", "reception_desk"]),
    ("hotel", "Have four guests in the bar and Priya by the lifts.", ["bar", "lift_lobby"]),
    ("residential", "Have two teenagers sprawled on the settee and Grandma at the cooker.", ["sofa", "kitchen_counter"]),
])
def test_a_name_after_and_in_a_placing_order_is_placed(read, world, prompt, places):
    groups = read(world, prompt).groups
    assert [g.location for g in groups] == places
    assert groups[-1].count.value == 1
