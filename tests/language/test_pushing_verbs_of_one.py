"""A pushing verb in "-s" the parser takes for a noun after one person (round 71): "a housekeeping
auxiliary wheels towels ...", read as "auxiliary wheels", a thing, so the person was lost."""

from __future__ import annotations

import pytest

CASES = [
    ("hotel", "Two porters wait in the lobby; a housekeeping auxiliary wheels towels from the laundry to the spa.",
     "spa"),
    ("hospital", "A nursing auxiliary wheels linen to ward 3.", "ward_c"),
]


@pytest.mark.parametrize(("world", "prompt", "place"), CASES)
def test_the_one_pushing_is_a_group(read, world, prompt, place):
    groups = read(world, prompt).groups
    pusher = groups[-1]
    assert pusher.count.value == 1 and pusher.intent == "walk" and pusher.destination == place
    assert all(g.intent != "walk" for g in groups[:-1])
