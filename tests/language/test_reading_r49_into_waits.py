"""Round 49: "N minutes into his wait in X, ..." is a stay of N minutes at X before the sentence's going;
"ten minutes into the park" is no stay."""

from __future__ import annotations

import pytest

from grove_tui.language.into_waits import with_stays_into


@pytest.mark.parametrize("world,prompt,start,destination,seconds", [
    ("hospital", "An hour into their break in the cafeteria, two nurses go back to the pharmacy.", "cafeteria",
     "pharmacy", 3600),
    ("mall", "Twenty minutes into her queue at the cinema, a teenager gives up and walks to the food court.",
     "cinema_lobby", "food_court", 1200),
])
def test_a_length_into_a_stay_is_the_stay_before_going(read, world, prompt, start, destination, seconds):
    (g,) = read(world, prompt).groups
    assert (g.start, g.destination, g.wait_seconds) == (start, destination, seconds)


def test_a_length_into_a_place_is_no_stay():
    assert with_stays_into("He walks ten minutes into the park.") == "He walks ten minutes into the park."
