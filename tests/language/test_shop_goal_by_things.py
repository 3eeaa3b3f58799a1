"""Wandering from one shop to another is browsing, but going to a shop said by what is there ("to where
the demo tables are") is a goal sought: they walk there."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt


@pytest.mark.parametrize("prompt,start,destination", [
    ("Two teens drift over from the bookshop to where the demo tables are.", "bookshop", "electronics_store"),
    ("Two teens amble from the toy shop to where the bookshelves are.", "toy_store", "bookshop"),
])
def test_a_shop_said_by_its_things_is_walked_to(worlds, prompt, start, destination):
    group = read_prompt(prompt, worlds["mall"]).groups[0]
    assert (group.intent, group.start, group.destination) == ("walk", start, destination), group


def test_between_shops_by_name_is_still_browsing(worlds):
    group = read_prompt("Two teens drift from the bookshop to the toy shop.", worlds["mall"]).groups[0]
    assert group.intent == "wander", group
