"""What a load moved by hand rides on ("on a sack truck", "in a wheelbarrow", "on a tray") is no
place: nothing refused, the route still read (load_carriers)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


@pytest.mark.parametrize("world, sentence, start, destination", [
    (W + "garden_centre.yaml", "A gardener carts compost in a wheelbarrow from the goods yard to the outdoor plants.",
     "goods_yard", "outdoor_plants"),
    (W + "parcel_depot.yaml", "A loader trundles three crates on a pallet truck from the inbound dock to the sorting floor.",
     "inbound_dock", "sorting_floor"),
    (W + "restaurant.yaml", "A waiter brings the desserts on a silver tray from the open kitchen out to the terrace.",
     "open_kitchen", "terrace"),
])
def test_what_carries_a_load_is_no_place(world, sentence, start, destination):
    reading = read_prompt(sentence, load_world(world))
    group = reading.groups[0]
    assert reading.unknown_places == ()
    assert (group.start, group.destination) == (start, destination)
