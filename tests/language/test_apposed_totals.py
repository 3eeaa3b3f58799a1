"""A count said as a total in apposition (language/count_tails.py, mentions.py): "the Saturday guides, six
volunteers in all, ...", "the night cleaners, twelve of them altogether, ...": how many the group is,
whatever noun the total uses; one group, not two."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,value,intent", [
    ("museum", "The Saturday guides, six volunteers in all, set off from the cafe for the entrance hall.", 6, "walk"),
    ("museum", "The Year 9 historians, twenty-eight pupils all told, wait in the entrance hall.", 28, "wait"),
    ("hospital", "The night cleaners, twelve of them altogether, walk from the cafeteria to ward B.", 12, "walk"),
    ("office", "The visiting auditors, five accountants in total, sit in the boardroom.", 5, None),
    ("station", "The Tuesday ramblers, fourteen walkers in all, wait on platform 1.", 14, "wait"),
])
def test_an_apposed_total_is_the_groups_count(read, world, prompt, value, intent):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    assert (groups[0].count.kind, groups[0].count.value) == ("exact", value)
    if intent is not None:
        assert groups[0].intent == intent


def test_a_part_said_after_a_full_count_stays_a_part(read):
    groups = read("hospital", "Ten nurses, two students among them, wait in the cafeteria.").groups
    assert groups[0].count.value == 10
