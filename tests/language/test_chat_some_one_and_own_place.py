"""Round 59 (r59a): in a verbless chat list "some" before one person is one person ("some woman at
reception"), and a bare word no list knows, placed in "his" or "her" own place ("gaffer in his office"),
is one person of its own item (language/some_one.py, language/own_place_items.py,
language/own_place_words.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,counts", [
    ("hospital", "some woman at reception, porter by the lifts", [1, 1]),
    ("mall", "some kid runs to the fountain while some shoppers browse", [1, 6]),
    ("office", "2 devs at the coffee machine, gaffer in his office", [2, 1]),
    ("hospital", "2 porters by the lifts, sister at her desk", [2, 1]),
    ("office", "3 interns at the printer, some bloke by the coffee machine, gaffer in his office", [3, 1, 1]),
])
def test_one_person_items_of_a_chat_list(read, world, prompt, counts):
    reading = read(world, prompt)
    assert [g.count.value for g in reading.groups] == counts


def test_some_before_many_is_left():
    from grove_tui.language.some_one import some_one

    assert some_one("some staff sweep") == "some staff sweep"
    assert some_one("some guys chat") == "some guys chat"
    assert some_one("Some guy waits") == "A guy waits"


def test_a_thing_in_his_place_is_no_one():
    from grove_tui.language.own_place_words import own_place

    assert own_place("gaffer", "in", "his")
    assert not own_place("gaffer", "in", "the")
    assert not own_place("robot", "in", "his")
