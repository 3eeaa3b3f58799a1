"""Round 54: the start or end of a span after "from", "since", "until" ("from first light", "since dawn",
"until closing time") is a time, not a place to refuse."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,location", [
    ("zoo", "Two keepers have waited by the penguin pool since dawn.", "penguin_pool_rail"),
    ("museum", "A dozen visitors stay in the café until closing time.", "cafe"),
    ("hospital", "Three porters wait in the cafeteria until dusk.", "cafeteria"),
    ("hospital", "Four visitors have sat in the cafeteria from first light.", "cafeteria"),
    ("museum", "Six pensioners linger in the café from opening time.", "cafe"),
])
def test_a_span_from_a_time_is_no_place(read, world, prompt, location):
    r = read(world, prompt)
    assert not r.unknown_places
    (g,) = r.groups
    assert g.location == location


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("mall", "Two teens walk from the food court to the cinema.", "food_court", "cinema_lobby"),
])
def test_a_place_after_from_stays(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.start, g.destination) == (start, destination)
