"""Round 44: a word for people the parser reads as an adverb or an adjective at the head of a list's first
item ("A cleaner hovers near the information desk, a pair of tourists push trolleys ..., and ...") is the
item's subject and its "-s" word the item's verb: one person there, not "hovers" as more people, nor the
verb's phrase run into the person."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,first,where", [
    ("airport", "A cleaner hovers near the information desk, a pair of tourists push trolleys from the check-in "
                "hall to gate A1, and a boy queues at the café.", "A cleaner", "information_desk"),
    ("airport", "A steward hovers near the information desk, a pair of tourists push trolleys from the check-in "
                "hall to gate A1, and a boy queues at the café.", "A steward", "information_desk"),
    ("hospital", "An orderly lurks near the pharmacy, two nurses chat at the nurses' station, and a porter waits "
                 "by the lifts.", "An orderly", "pharmacy"),
])
def test_a_mistagged_person_heads_the_first_item(read, world, prompt, first, where):
    groups = read(world, prompt).groups
    assert len(groups) == 3
    assert (groups[0].who, groups[0].count.value, groups[0].intent, groups[0].location) == (first, 1, "wait", where)


def test_the_other_items_keep_their_reading(read):
    groups = read("airport", "A cleaner hovers near the information desk, a pair of tourists push trolleys from the "
                             "check-in hall to gate A1, and a boy queues at the café.").groups
    assert (groups[1].count.value, groups[1].intent, groups[1].destination) == (2, "walk", "gate_a1")
    assert (groups[2].intent, groups[2].location) == ("queue", "cafe")
