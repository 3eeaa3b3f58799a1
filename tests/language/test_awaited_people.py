"""The people a waiting robot waits for are at the place of what they do (issue 29): "the robot waits
for N X to <verb> ... at P" puts them at P. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, place", [
    ("hospital", "The robot waits for three nurses to leave the lift at the main entrance.", "main_entrance"),
    ("mall", "The robot patiently waits for two shoppers to finish queueing at the cinema.", "cinema_lobby"),
])
def test_the_awaited_are_at_the_place_of_what_they_do(read, world, prompt, place):
    reading = read(world, prompt)
    group = reading.groups[0]
    assert place in (group.location, group.destination)
    assert reading.robot is not None and reading.robot.location == place


def test_a_place_said_before_for_is_the_robots_only(read):
    reading = read("hospital", "The robot waits by the pharmacy for two porters to come.")
    assert "pharmacy" not in (reading.groups[0].location, reading.groups[0].destination)
