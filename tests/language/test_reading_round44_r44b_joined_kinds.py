"""Round 44 (r44b): one count before two kinds of people joined by "and" ("twenty-two boys and girls",
"ten men and women", "a dozen mums and dads"): the count is of both, one group; in apposition after a
collective ("The choir, ... in all, ...") it says how many the collective is (language/joined_kinds.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,kind,value", [
    ("museum", "Twenty boys and girls walk from the cloakroom to the cafe.", "exact", 20),
    ("mall", "About 40 mums and dads wait by the fountain.", "approximate", 40),
    ("hospital", "Ten men and women queue at the pharmacy.", "exact", 10),
    ("museum", "The school party, thirty boys and girls all told, walks to the cafe.", "exact", 30),
    ("concert_venue", "The orchestra, sixty men and women in all, files from the green room onto the stage.",
     "exact", 60),
])
def test_one_count_of_two_joined_kinds_is_one_group(read, world, prompt, kind, value):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value) == (kind, value)


@pytest.mark.parametrize("world,prompt,counts", [
    ("museum", "Two nurses and three doctors walk to the cafe.", [2, 3]),
    ("museum", "Ten kids and their parents walk to the cafe.", [10, 2]),
])
def test_kinds_with_their_own_count_or_determiner_stay_two_groups(read, world, prompt, counts):
    assert [g.count.value for g in read(world, prompt).groups] == counts
