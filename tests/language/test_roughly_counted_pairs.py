"""Round 55 (r55a): a rough count before two kinds joined by "and" ("the twenty or so owners and
staff", "thirty-odd parents and teachers") is one group of about that many, not the count's kind and a
vague few of the other (language/counted_lists.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,value", [
    ("hotel", "The thirty or so guests and staff in the bar leave by the fire exit.", 30),
    ("primary_school", "Thirty-odd parents and teachers wait in the hall.", 30),
    ("marina", "A yacht catches fire at the fuel berth and the fifty or so owners and visitors on pontoon B "
     "hurry out through the car park.", 50),
])
def test_a_rough_count_before_two_kinds_is_one_group(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert group.count.value == value and group.count.kind == "approximate"
