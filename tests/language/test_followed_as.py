"""The robot following someone "as he walks from X to Y": the route is the person's (followed_as)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


@pytest.mark.parametrize("world, sentence, who, start, destination", [
    (W + "care_home.yaml", "The robot shadows Mrs Patel as she totters from the lounge over to the dining room.",
     "Mrs Patel", "lounge", "dining_room"),
    (W + "aquarium.yaml", "The robot trails a small boy while he runs from the gift shop to the shark tunnel.",
     "a small boy", "gift_shop", "shark_tunnel"),
])
def test_the_person_followed_walks_the_route_of_the_as_clause(world, sentence, who, start, destination):
    reading = read_prompt(sentence, load_world(world))
    g = reading.groups[0]
    assert (g.intent, g.start, g.destination) == ("walk", start, destination)
    assert reading.robot is not None and reading.robot.task == "follow"
