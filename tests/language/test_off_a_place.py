""""off" a place is where people set out, whatever the parser makes of it: a load named by a gerund
("a basket of washing off the balcony") is no verb with a particle (language/gerund_loads.py), a thing
taken off a place is the taker walking from there (language/taken_off.py), and "in off the balcony"
starts there (roles.py)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

OFF = [
    ("residential", "Mum carries a basket of washing off the balcony.", "balcony", None),
    ("residential", "Dad lugs a bag of ironing off the balcony into the bedroom.", "balcony", "master_bedroom"),
    ("mall", "A cleaner carries a bucket of mopping water off the food court.", "food_court", None),
    ("residential", "Dad takes the bins off the patio.", "balcony", None),
    ("station", "Two porters take the luggage trolley off platform 2.", "platform_2", None),
    ("residential", "Mum brings the laundry in off the balcony.", "balcony", None),
]


@pytest.mark.parametrize("world, sentence, start, destination", OFF)
def test_off_a_place_is_the_start(world, sentence, start, destination):
    reading = read_prompt(sentence, load_world(world))
    group = reading.groups[0]
    assert (group.intent, group.start, group.destination) == ("walk", start, destination)


def test_a_thing_taken_off_no_place_is_no_walk():
    reading = read_prompt("Dad takes the lid off the pan.", load_world("residential"))
    assert reading.groups[0].intent != "walk" and reading.groups[0].start is None
