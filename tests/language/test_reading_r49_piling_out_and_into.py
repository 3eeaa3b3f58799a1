"""Round 49: a crowd piling out of one place "and into" another walks there; the "and" joins the same
going on, it does not end the clause. With a hazard said, piling out is still an evacuation."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "A coachload of visitors pile out of the cafeteria and into the main waiting room.", "cafeteria",
     "main_waiting_room"),
    ("mall", "The kids bail out of the cinema and onto the food court.", "cinema_lobby", "food_court"),
])
def test_piling_out_and_into_a_place_is_walking(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.start, g.destination) == ("walk", start, destination)


def test_piling_out_from_a_hazard_is_still_evacuating(read):
    (g,) = read("hospital", "Smoke fills the cafeteria and the visitors pile out and into the car park.").groups
    assert g.intent == "evacuate"
