"""A person who acts on their own room and then takes something somewhere ("locks his office and takes
the minutes across to the chamber") starts in that room: taking a thing to a place is setting off
(language/carried_moves.py). Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, destination", [
    ("town_hall", "The mayor shuts his office and takes the minutes across to the council chamber.", "mayors_parlour",
     "council_chamber"),
    ("residential", "The children tidy their bedroom and take the toys down to the living room.", "child_bedroom",
     "living_room"),
    ("golf_club", "Margaret Fenwick tidies her office and brings the scorecards over to the pro shop.",
     "secretary_office", "pro_shop"),
])
def test_the_room_acted_on_is_where_they_start(read, world, prompt, start, destination):
    group = read(world, prompt).groups[0]
    assert (group.start, group.destination) == (start, destination)


def test_taking_the_stairs_is_no_start(read):
    group = read("town_hall", "Two clerks take the stairs to the council chamber.").groups[0]
    assert (group.start, group.destination) == (None, "council_chamber")
