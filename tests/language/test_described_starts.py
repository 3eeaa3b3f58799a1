"""A place that says who people are ("tourists off the coaches") gives way to the start the clause says
after its verb ("stream from the coach park"), though the place before names a fixture of it
(language/descriptor_starts.py); said alone it is still where they start."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

OUTLET = "eval/understanding/worlds/outlet_village.yaml"
SQUARE = "eval/understanding/worlds/town_square.yaml"
STARTS = [
    (OUTLET, "Some thirty day-trippers off the coaches wander from the coach park over to the food hall.",
     "coach_park"),
    (SQUARE, "Twenty pupils off the buses troop from the taxi rank to the bandstand.", "taxi_rank"),
    (OUTLET, "Forty tourists off the coaches walk to the designer arcade.", "coach_bays"),
]


@pytest.mark.parametrize("world, sentence, start", STARTS)
def test_the_start_after_the_verb_wins_over_who_they_are(world, sentence, start):
    reading = read_prompt(sentence, load_world(world))
    assert reading.groups[0].start == start
