"""Round 70 (r70a): a subject list of three or more names ("Tariq, Lena and Bea wander ...", "Ola, Ben
and their nan head ...") is one group of that many, not a group per name (language/named_lists.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,value", [
    ("hospital", "Tariq, Lena, Bea and their nan wander from the cafeteria to ward C.", 4),
    ("hospital", "Ola, Ben and Kit from pharmacy amble from the cafeteria to radiology.", 3),
    ("office", "Mia, Tom and their boss shuffle out of the kitchen into the boardroom.", 3),
])
def test_a_list_of_names_is_one_group(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert group.count.value == value
