"""Round 54 (r54a): a chat list of counted items, each "<count> <noun> <at> <place>", is one group per
item, though one item's noun is a word the reader does not know (language/chat_list_items.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,counts", [
    ("hospital", "approx 12 visitors in the canteen, 3 sonographers at reception, 2 porters by the lifts", [12, 3, 2]),
    ("hotel", "4 guests @ bar, 1 concierge-bot tech by the lifts, 2 cleaners in the lobby", [4, 1, 2]),
    ("office", "6 ppl in mtg room 1, 1 devops in comms room", [6, 1]),
])
def test_each_counted_item_is_a_group(read, world, prompt, counts):
    assert [g.count.value for g in read(world, prompt).groups] == counts


def test_a_thing_counted_in_the_list_is_no_one(read):
    groups = read("hotel", "about 20 guests in the bar, 2 suitcases by the lifts").groups
    assert [g.count.value for g in groups] == [20]
