"""Round 49 (r49b): a thing that catches fire or blows up, said as a bare subject ("Fat flares up on
the grill", "Butter catches fire in the pan"), is nobody: only the people who flee are a group
(language/hazard_subjects.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,label", [
    ("restaurant", "Butter catches fire in the pan and the ten cooks in the open kitchen run to the delivery door.",
     "cook"),
    ("hotel", "Paper ignites in the lobby and twenty guests hurry out of the bar.", "guest"),
    ("hotel", "Toast catches fire in the kitchen and twelve guests leave the bar.", "guest"),
    ("restaurant", "Fat flares up on the grill and the fifteen or so cooks in the open kitchen escape through the "
     "delivery door.", "cook"),
])
def test_a_burning_thing_is_nobody(read, world, prompt, label):
    reading = read(world, prompt)
    assert [g.label for g in reading.groups] == [label]


def test_a_person_who_burns_a_thing_is_still_a_person(read):
    reading = read("hotel", "A cleaner burns the toast in the kitchen.")
    assert [g.label for g in reading.groups] == ["cleaner"]
