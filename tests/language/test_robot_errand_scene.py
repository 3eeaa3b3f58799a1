"""A robot's errand that names nobody ("the robot brings a sack of ice from the cellar to the bar") is read
as "the robot crosses the lobby" is: one group of people left to the model, marked assumed, never no one
(a reading with no group makes `grove generate` refuse the sentence as leaving nobody in the scenario)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("station", "The robot carries a crate of water from the ticket office to platform 2."),
    ("hotel", "The robot brings a stack of towels up from the laundry to room 108."),
    ("museum", "The robot patrols the great hall."),
])
def test_errand_alone_leaves_people_to_the_model(read, world, prompt):
    reading = read(world, prompt)
    (group,) = reading.groups
    assert group.who == "people" and reading.problems == ()
    assert any(c.field == "group" and c.score < 0.5 for c in group.confidence)
