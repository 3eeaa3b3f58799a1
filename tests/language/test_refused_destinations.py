"""A stroll "to"/"towards" a place the world lacks is still a walk somewhere, not a wander: the place is
refused and the intent stays walk (refused_destinations)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


@pytest.mark.parametrize("world, sentence, refused", [
    (W + "stadium.yaml", "Three mates amble out of the family zone towards the beer marquee.", "beer marquee"),
    (W + "theme_park.yaml", "Two teens stroll out of the souvenir shop towards the photo tent.", "photo tent"),
    (W + "cricket_ground.yaml", "A foursome of lads stroll out of the tea room to the crazy golf.", "crazy golf"),
])
def test_a_refused_destination_is_still_one(world, sentence, refused):
    reading = read_prompt(sentence, load_world(world))
    assert reading.unknown_places == (refused,)
    assert reading.groups[0].intent == "walk"
