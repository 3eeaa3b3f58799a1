"""Round 58 (r58c): a verbless kin couple before a place ("Gran and Grandad in the garden, ...",
"Husband and wife at the pharmacy, ...") is one group of two, as it is with a verb
(language/verbless_pairs.py, language/couples.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,counts,places", [
    ("residential", "Gran and Grandad in the garden, the kids in the living room.", [2, None], ["balcony", "living_room"]),
    ("hospital", "Husband and wife at the pharmacy, the kids in the canteen.", [2, None], ["pharmacy", "cafeteria"]),
    ("residential", "Mum and Dad at the kitchen table, the kids in the living room.", [2, None],
     ["dining_table", "living_room"]),
])
def test_a_verbless_couple_before_a_place_is_one_group_of_two(read, world, prompt, counts, places):
    groups = read(world, prompt).groups
    assert [g.count.value if n is not None else None for g, n in zip(groups, counts)] == counts
    assert [g.location for g in groups] == places


def test_two_people_not_a_couple_stay_two_groups(read):
    groups = read("hospital", "A nurse and a porter by the pharmacy, two visitors in the canteen.").groups
    assert [g.count.value for g in groups] == [1, 1, 2]
