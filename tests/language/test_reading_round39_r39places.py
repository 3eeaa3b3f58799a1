"""Place classes of round 39 (r39places), each with sentences of its own over at least two worlds (none
from the understanding sets): a fixture people busy themselves with ("tinker with the pinsetters",
"fiddle about with the fountain") or look over ("check out the SUV") is where they are."""

from __future__ import annotations

import pytest


# ---- 1. a fixture handled or looked over is where people are -----------------------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("bowling_alley", "Two lane mechanics fiddle about with the pinsetters.", "pinsetters"),
    ("bowling_alley", "Two technicians tamper with the pinsetters all evening.", "pinsetters"),
    ("mall", "Three kids mess about with the fountain.", "fountain"),
    ("car_showroom", "Two brothers check out the hatchback.", "display_hatchback"),
    ("car_showroom", "a retired pair checking out the electric car", "display_ev"),
    ("mall", "Two plumbers tinker with the fountain.", "fountain"),
    ("mall", "A plumber tinkers with the fountain.", "fountain"),
    ("bowling_alley", "A lane mechanic fiddles about with the pinsetters.", "pinsetters"),
])
def test_a_fixture_handled_or_looked_over_is_the_location(read, world, prompt, location):
    (group,) = read(world, prompt).groups
    assert group.location == location


# ---- guards: "with" a thing or a person, "check out" as leaving keep no place ----------------------------

@pytest.mark.parametrize("world,prompt", [
    ("bowling_alley", "A mechanic tinkers with his phone."),
    ("mall", "Three kids play with a ball."),
    ("hotel", "A guest checks out early."),
])
def test_a_thing_or_leaving_is_no_location(read, world, prompt):
    (group,) = read(world, prompt).groups
    assert group.location is None
