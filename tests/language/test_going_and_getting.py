"""Going "and" getting something from a place is going there for it (gone_and_done.going_to_get)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


@pytest.mark.parametrize("world, sentence, destination, purpose", [
    (W + "aquarium.yaml", "Two teenagers go and buy ice lollies from the cafe.", "cafe", "ice lollies"),
    (W + "campsite.yaml", "A camper nips and gets some milk from the camp shop.", "camp_shop", "milk"),
    (W + "bus_station.yaml", "Three students went and grabbed coffees from the cafe.", "cafe", "coffees"),
])
def test_going_and_getting_a_thing_from_a_place_goes_there_for_it(world, sentence, destination, purpose):
    g = read_prompt(sentence, load_world(world)).groups[0]
    assert g.destination == destination and purpose in (g.purpose or "")
