"""Clothes someone owns ("in their best coats", "in her coat") are no room, whatever verb follows, even in a
world where a place is called by the clothing word (the bingo hall's coat rails, "coats"; the cookery school's
cloakroom, "coats"); a place named after the clothes stays a place (language/worn_clothes.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count,location", [
    ("bingo_hall", "Twenty regulars in their best coats wait in the foyer.", 20, "foyer"),
    ("cookery_school", "Six students in their coats queue at the reception desk.", 6, "reception_desk"),
    ("bingo_hall", "A girl in her coat waits by the coat rails.", 1, "coat_rails"),
])
def test_owned_clothes_are_no_place(read, world, prompt, count, location):
    reading = read(world, prompt)
    (group,) = reading.groups
    assert reading.unknown_places == ()
    assert group.count.value == count and group.location == location
