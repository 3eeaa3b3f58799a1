"""Round 49 (r49b): a number with "-some" after it ("sixty-some moviegoers", "twenty-some nurses") is
about that many, as "twenty-odd" is, not a vague "some" (language/counts.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,value", [
    ("hospital", "Twenty-some nurses wait in the canteen.", 20),
    ("hotel", "Forty-some guests drink at the bar.", 40),
    ("mall", "At 3pm on Saturday, sixty-some moviegoers troop out of the food hall toward the cinema.", 60),
])
def test_a_number_and_some_is_about_that_many(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert group.count.kind == "approximate" and group.count.value == value
    assert group.count.low < value < group.count.high
