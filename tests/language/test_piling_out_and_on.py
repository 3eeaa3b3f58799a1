"""A crowd piling out of one place "and across to" another, nothing urgent said, walks there."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


@pytest.mark.parametrize("world, sentence, start, destination", [
    (W + "ferry_terminal.yaml", "When the boarding call comes, the passengers pile out of the café and down to the gangway.",
     "cafe", "gangway_1"),
    (W + "stadium.yaml", "At the final whistle the fans pile out of the stands and over to the exits.", "south_stand",
     "gate_b"),
])
def test_piling_out_and_on_to_a_place_is_walking(world, sentence, start, destination):
    g = read_prompt(sentence, load_world(world)).groups[0]
    assert (g.intent, g.start, g.destination) == ("walk", start, destination)


def test_piling_out_with_nowhere_to_go_is_still_leaving_in_a_hurry():
    g = read_prompt("The fans pile out of the stands.", load_world(W + "stadium.yaml")).groups[0]
    assert g.intent == "evacuate"
