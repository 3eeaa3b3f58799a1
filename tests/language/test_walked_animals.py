"""Walking an animal in a place ("walking dogs in the paddock", "walks his dog on the lake shore") is being
there, not setting off from it (walked_animals.py); walking one from a place to another is still a walk."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,place", [
    ("campsite", "A man walks his dog on the lake shore.", "lake_shore"),
    ("campsite", "Two girls walking a puppy in the playground.", "playground"),
    ("city_farm", "A volunteer walks the goats round the farmyard.", "farmyard"),
    ("animal_shelter", "3 vols @ rota board, 2 more walkin dogs in paddock", "exercise_paddock"),
])
def test_walking_an_animal_there_is_being_there(read, world, prompt, place):
    group = read(world, prompt).groups[-1]
    assert group.location == place and group.start is None and group.intent == "wander"


def test_walking_an_animal_somewhere_else_is_a_walk(read):
    (group,) = read("campsite", "A man walks his dog from the tent field to the lake shore.").groups
    assert (group.intent, group.start, group.destination) == ("walk", "tent_field", "lake_shore")
