"""People on a lesson who "head for" somewhere: "head" is their verb, not the last word of a place, and
the lesson they are on is no place (language/heading_verbs.py, courses_taken.py). A place's own name
with a verb-like word stays whole."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,destination", [
    ("ice_rink", "The twelve children on the Sunday lesson head for the cafe.", "cafe"),
    ("swimming_baths", "The six kids on the early lesson head to the cafe after their swim.", "cafe"),
    ("riding_stables", "Four women on the beginners' lesson head off to the tack room.", "tack_room"),
])
def test_head_after_a_lesson_is_the_verb(read, world, prompt, destination):
    r = read(world, prompt)
    (g,) = r.groups
    assert g.destination == destination
    assert r.unknown_places == ()


def test_a_place_name_before_to_stays_whole(read):
    (g,) = read("mall", "Five girls walk from the toy shop to the bookshop.").groups
    assert (g.start, g.destination) == ("toy_store", "bookshop")
