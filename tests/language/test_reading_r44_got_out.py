"""Round 44: an order to get people out ("Fire in the kitchen: get the twenty visitors in the cafeteria out
through the main entrance") is their leaving, from where they are by the way said: an evacuation when a
hazard is named. An object that is no one ("get the bins out") is no group."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count,start,destination", [
    ("hospital", "Fire in the kitchen: get the twenty visitors in the cafeteria out through the main entrance.", 20,
     "cafeteria", "main_entrance"),
    ("hospital", "Smoke in the pharmacy! Move the patients in the waiting room out via the main entrance.", None,
     "main_waiting_room", "main_entrance"),
    ("mall", "Gas leak in the food court: get the fifty-odd shoppers in the supermarket out by the supermarket door.",
     50, "supermarket", None),
])
def test_an_order_to_get_people_out_is_their_evacuation(read, world, prompt, count, start, destination):
    reading = read(world, prompt)
    (g,) = reading.groups
    assert (g.intent, g.start) == ("evacuate", start)
    assert count is None or g.count.value == count
    assert destination is None or g.destination == destination


def test_an_order_to_get_things_out_names_no_one(read):
    reading = read("karting_centre", "Get the bins out by the café street door.")
    assert all(g.label != "bin" for g in reading.groups)
