"""Round 44 (r44b): a bare count said by the outing the people are on ("About twenty on the brewery tour
...", "Thirty on the guided tour walk ...", "a dozen off the coach head ..."): so many people, one group;
the outing's noun is no second group (language/counted_outings.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,kind,value,intent", [
    ("museum", "Thirty on the guided tour walk to the cafe.", "exact", 30, "walk"),
    ("brewery", "About twenty on the brewery tour wait in the tap room.", "approximate", 20, "wait"),
    ("brewery", "A dozen from the stag party queue at the tasting bar.", "exact", 12, "queue"),
    ("zoo", "Some forty on the school trip crowd round the penguin pool.", "approximate", 40, "wait"),
])
def test_a_bare_count_on_an_outing_is_one_group(read, world, prompt, kind, value, intent):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value, group.intent) == (kind, value, intent)


def test_a_count_on_an_outing_after_another_group(read):
    a, b = read("museum", "Two guards wait in the lobby, and a dozen off the coach head to the cafe.").groups
    assert (a.count.value, b.count.value, b.destination) == (2, 12, "cafe")
