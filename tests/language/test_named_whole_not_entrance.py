"""A place named whole by one of its own names is that place, though its name holds a word of the
building ("the front stables" of a riding school: "stables" is the world's own word, and "front" alone
would be the way in): place_entrance.named_whole. No other shipped or eval world has a "front <its own
name>" place, so the sentences are of the riding school in other words; "the front" is still the way in."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("prompt, start, destination", [
    ("The farrier lugs his toolbox from the car park across to the front stables.", "car_park", "front_stables"),
    ("Two grooms wheel a barrow back to the front stables from the muck heap.", "muck_heap", "front_stables"),
    ("A mum and her daughter wander from the front stables over to the tack room.", "front_stables", "tack_room"),
])
def test_the_named_place_is_read(read, prompt, start, destination):
    g = read("riding_stables", prompt).groups[0]
    assert (g.start, g.destination) == (start, destination)


def test_the_front_alone_is_still_the_way_in(read):
    assert read("riding_stables", "Two grooms walk to the front.").groups[0].destination == "yard_entrance"
