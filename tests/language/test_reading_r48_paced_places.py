"""A verb of going about a place with the place as its object ("paces the corridor", "prowls the food
court", "patrols the concourse") says where the people are: the object is their location
(lexicon.LOCATION_OBJECT_VERBS)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,location", [
    ("mall", "A nervous father paces the food court.", "food_court"),
    ("hospital", "A worried husband paces the corridor outside the ward.", "main_corridor"),
    ("hospital", "A doctor paces up and down the waiting room.", "main_waiting_room"),
    ("mall", "A security guard patrols the food court.", "food_court"),
])
def test_the_paced_place_is_where_they_are(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.location) == ("wander", location)


def test_prowling_a_room_is_wandering_there(read):
    (g,) = read("community_centre", "Two caretakers prowl the main hall after the disco.").groups
    assert g.intent == "wander"
    assert g.location == "main_hall"
