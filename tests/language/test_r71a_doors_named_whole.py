"""A door of a room named whole with the room ("the fire door in the Egyptian gallery", "the side door of the
isolation unit") is that door, not the room's main door that "door" alone would mean
(language/place_of_zone.py thing_of_named_zone)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, door", [
    ("museum", "Two visitors slip out by the fire door in the Egyptian gallery.", "fire_exit"),
    ("animal_shelter", "A volunteer carries a sick puppy out through the side door of the isolation unit.",
     "isolation_outside_door"),
])
def test_a_door_named_whole_with_its_room_is_that_door(read, world, prompt, door):
    assert read(world, prompt).groups[0].destination == door


def test_the_door_of_a_room_is_still_its_main_door(read):
    assert read("museum", "Two visitors leave through the door of the Egyptian gallery.").groups[0].destination \
        == "egyptian_gallery_arch"
