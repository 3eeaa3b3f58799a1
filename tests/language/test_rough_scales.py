"""Round 55 (r55a): "a dozen or so", "a score or so" said before people are about that many, not a
vague few (language/rough_scales.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,value", [
    ("hotel", "A score or so guests wait in the lobby.", 20),
    ("hospice", "A dozen or so visitors gather in the lounge.", 12),
    ("hotel", "The guests, a dozen or so, wait in the lobby.", 12),
])
def test_a_rough_scale_is_about_that_many(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert group.count.kind == "approximate" and group.count.value == value
