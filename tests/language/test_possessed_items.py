"""Verbless chat items opened by a possessive (language/possessed_items.py): "my wife in the spa, our
kids at the pool" names two groups, each at its place; an item whose person has a verb is left alone."""

from __future__ import annotations

import pytest

from grove_tui.language.possessed_items import possessed_items


@pytest.mark.parametrize("typed,read", [
    ("my wife in the spa, our kids at the pool", "the wife in the spa, the kids at the pool"),
    ("our son is in bedroom 2", "our son is in bedroom 2"),
    ("Their car in the car park", "Their car in the car park"),
])
def test_possessed_items(typed, read):
    assert possessed_items(typed) == read


@pytest.mark.parametrize("world,prompt,locations", [
    ("hotel", "my wife in the spa, our kids at the pool, the nanny reading in the lobby",
     ["spa", "swimming_pool", "lobby"]),
    ("hospital", "My husband in the cafeteria, our daughter at the pharmacy", ["cafeteria", "pharmacy"]),
    ("residential", "our son on his xbox in bedroom 2, the missus @ kitchen table, gran napping in the armchair",
     ["child_bedroom", "dining_table", "armchair"]),
])
def test_possessed_items_are_groups(read, world, prompt, locations):
    reading = read(world, prompt)
    assert [g.location for g in reading.groups] == locations
