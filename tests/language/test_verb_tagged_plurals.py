"""Round 55 (r55a): a counted two-word plural person the parser took for a verb ("two bell hops idle",
"three deck hands lounge") is the group the count counts, and the plain verb after it is what they
do (language/verb_tagged_plurals.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,first,groups", [
    ("hotel", "Two bell hops wait at the bell desk.", 2, 1),
    ("marina", "Three deck hands lounge on the quayside benches while two sailors walk to the chandlery.", 3, 2),
    ("hotel", "Four bell hops loiter by the lifts, and a guest queues at reception.", 4, 2),
])
def test_a_counted_plural_tagged_a_verb_is_the_group(read, world, prompt, first, groups):
    read_groups = read(world, prompt).groups
    assert len(read_groups) == groups
    assert read_groups[0].count.value == first and read_groups[0].intent == "wait"
