"""Things carried, listed with "and" and holding "-ing" contents ("a bag of shopping"), cast no activity; a
thing gone to whose word only modifies place names ("their boat", of "boat shop") leaves the place after it
as where they go (contents_of, to_things)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


@pytest.mark.parametrize("world, sentence, start, destination", [
    (W + "campsite.yaml", "Two campers lug a cool box and a bag of shopping from the car park up to the tent field.",
     "car_park", "tent_field"),
    (W + "campsite.yaml", "A dad carries a rucksack and a tub of washing from the shower block over to the laundry room.",
     "shower_block", "laundry_room"),
    (W + "marina.yaml", "A skipper hauls a sail bag from the boatyard down to her boat on pontoon A.",
     "boatyard", "pontoon_a"),
])
def test_carried_things_walk_from_one_place_to_another(world, sentence, start, destination):
    g = read_prompt(sentence, load_world(world)).groups[0]
    assert (g.intent, g.start, g.destination) == ("walk", start, destination)
