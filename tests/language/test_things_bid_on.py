"""Round 54: what someone bids on, loses out on or came for is a thing, no place to refuse."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start", [
    ("auction_house", "Having missed out on the oak dresser, two collectors leave the saleroom.", "main_saleroom"),
    ("auction_house", "A dealer who lost out on the walnut bureau leaves the saleroom.", "main_saleroom"),
    ("car_showroom", "Having missed out on the red convertible he came for, a buyer walks out of the showroom.",
     "showroom"),
])
def test_a_thing_lost_out_on_is_no_place(read, world, prompt, start):
    r = read(world, prompt)
    assert not r.unknown_places
    (g,) = r.groups
    assert g.start == start


@pytest.mark.parametrize("world,prompt,location", [
    ("auction_house", "A dealer bids on the Georgian bureau in the saleroom.", "main_saleroom"),
    ("market_hall", "Two shoppers haggle over the copper kettle at the entrance hall.", "entrance_hall"),
])
def test_a_thing_bid_on_is_no_place(read, world, prompt, location):
    r = read(world, prompt)
    assert not r.unknown_places
    (g,) = r.groups
    assert g.location == location


def test_a_place_after_on_stays(read):
    (g,) = read("mall", "Two teens wait on the bench by the fountain.").groups
    assert g.location is not None
