""""in the direction of X", "in X's direction": where someone heads, as "towards X" (direction_phrases);
a place the world lacks is refused, one it has is the destination."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, destination", [
    ("zoo", "Three keepers walk from the gift shop in the direction of the main gate.", "gift_shop", "main_gate"),
    ("zoo", "A family wander off in the gift shop's direction.", None, "gift_shop"),
    ("library", "A student heads in the general direction of the lockers.", None, "bag_lockers"),
])
def test_direction_names_the_destination(read, world, prompt, start, destination):
    g = read(world, prompt).groups[0]
    assert (g.start, g.destination) == (start, destination)


@pytest.mark.parametrize("world, prompt, refused", [
    ("zoo", "Two kids run in the general direction of the planetarium.", "planetarium"),
    ("library", "Two readers drift from the foyer in the direction of the bowling alley.", "bowling alley"),
])
def test_a_direction_the_world_lacks_is_refused(read, world, prompt, refused):
    r = read(world, prompt)
    assert r.unknown_places == (refused,)
    assert r.groups[0].destination is None
