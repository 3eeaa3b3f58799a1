"""A place abandoned or deserted "for" another (issue 29): they go from the first to the second, as with
"leaves X for Y"; "abandons hope and trudges to X" keeps its reading. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, goal", [
    ("hospital", "Four nurses desert the cafeteria for the main entrance.", "cafeteria", "main_entrance"),
    ("mall", "Three shoppers abandon the food court for the cinema.", "food_court", "cinema_lobby"),
])
def test_a_place_abandoned_for_another_is_a_walk_between_them(read, world, prompt, start, goal):
    group = read(world, prompt).groups[0]
    assert group.intent == "walk"
    assert (group.start, group.destination) == (start, goal)


def test_abandoning_hope_is_no_place_left(read):
    group = read("airport", "Having waited a quarter of an hour at carousel 2, a backpacker abandons hope and "
                 "trudges to the baggage services desk.").groups[0]
    assert (group.start, group.destination) == ("carousel_2", "lost_luggage_desk")
