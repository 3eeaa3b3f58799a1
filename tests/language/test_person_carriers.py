"""What a person rides in while moved along ("in a wheelchair", "on a stretcher", "in a buggy"), however far
after the verb of moving, is no place: nothing refused, the route still read (person_carriers)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


@pytest.mark.parametrize("world, sentence, start, destination", [
    (W + "stadium.yaml", "A steward helps the fainted fan down from the north stand, along the west link and into the "
     "first aid room in a wheelchair.", "north_stand", "first_aid_room"),
    (W + "theme_park.yaml", "A dad pushes his sleepy toddler out of the souvenir shop and back to the entrance plaza "
     "in a buggy.", "souvenir_shop", "entrance_plaza"),
    (W + "cricket_ground.yaml", "The physio wheels the injured opener off the outfield and round to the home dressing "
     "room in a wheelchair.", "outfield", "home_dressing_room"),
])
def test_what_a_person_rides_in_is_no_place(world, sentence, start, destination):
    reading = read_prompt(sentence, load_world(world))
    assert reading.unknown_places == ()
    assert (reading.groups[0].start, reading.groups[0].destination) == (start, destination)
