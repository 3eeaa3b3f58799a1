"""Round 56 (r56a): "a father-and-daughter pair", "a husband and wife team" is one group of two, not a
person beside a pair (language/paired_kin.py); and a verb the parser takes for a noun after the
collective ("a pair solder at the bench and ...") is the pair's verb (language/collective_verbs.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,counts,places", [
    ("hospital", "A mother-and-son pair wait in the canteen.", [2], ["cafeteria"]),
    ("hotel", "A husband and wife team check in at reception.", [2], ["reception_desk"]),
    ("hotel", "A mother-and-son pair wait in the bar and a husband and wife couple check in at reception.",
     [2, 2], ["bar", "reception_desk"]),
    ("hospital", "While a porter mops the corridor, a couple queue at the pharmacy and three visitors sit in "
                 "the canteen.", [1, 2, 3], ["main_corridor", "pharmacy", "cafeteria"]),
])
def test_a_pair_named_by_two_people_is_one_group_of_two(read, world, prompt, counts, places):
    groups = read(world, prompt).groups
    assert [g.count.value for g in groups] == counts
    assert [g.location for g in groups] == places
