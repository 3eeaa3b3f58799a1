"""Round 57 (r57c): a counted two-word plural person whose first word names a place of the world and
whose last word is also a thing ("kitchen hands", "bar hands", "stage hands"), then a people's verb in
its plain form the parser took for a noun or adjective, is one group of that count
(language/verb_tagged_plurals.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count,groups", [
    ("restaurant", "A pair of kitchen hands loiter by the back door.", 2, 1),
    ("bowling_alley", "Two bar hands idle by the entrance.", 2, 1),
    ("playhouse", "A trio of stage hands linger by the dock doors while an usher walks to the foyer.", 3, 2),
])
def test_a_counted_compound_person_is_one_group(read, world, prompt, count, groups):
    read_groups = read(world, prompt).groups
    assert len(read_groups) == groups
    assert read_groups[0].count.value == count and read_groups[0].label == "hand"
