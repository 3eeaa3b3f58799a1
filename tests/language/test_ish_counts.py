""""-ish" on a number word or on "a dozen" ("a dozen-ish teenagers", "six-ish cyclists"): about so many."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,value", [
    ("cinema", "A dozen-ish teenagers hang around by the popcorn stand.", 12),
    ("library", "Half a dozen-ish students drift into the reading room.", 6),
    ("zoo", "Eight-ish schoolkids queue at the ice cream kiosk.", 8),
])
def test_ish_after_a_number_word_is_approximate(read, world, prompt, value):
    groups = read(world, prompt).groups
    assert len(groups) == 1, groups
    assert groups[0].count.kind == "approximate" and groups[0].count.value == value, groups[0]


def test_ish_on_another_word_is_no_count(read):
    groups = read("hospital", "A tallish man walks to the cafeteria.").groups
    assert len(groups) == 1 and groups[0].count.value == 1, groups
