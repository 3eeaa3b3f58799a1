"""The robot's trip said with "off" ("brings folded towels in off the balcony to the bathroom", "rolls off
platform 2 and over to the cafe"): the place it comes off is where it starts, as "from" says, not a
place it passes. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, destination", [
    ("residential", "The robot brings folded towels in off the balcony to the bathroom while our lodger has a lie-in.",
     "balcony", "bathroom"),
    ("station", "The robot rolls off platform 2 and over to the cafe.", "platform_2", "cafe"),
    ("museum", "The robot carries the chairs off the stage to the auditorium store.", "stage", "auditorium"),
])
def test_the_robot_starts_where_it_comes_off(read, world, prompt, start, destination):
    robot = read(world, prompt).robot
    assert (robot.start, robot.destination) == (start, destination)
    assert start not in robot.via
