"""People said first, then taken somewhere by the robot in its own later clause ("..., and the robot
escorts them to the main entrance"): they follow the robot from where they are to where it takes them,
and the robot starts there (language/robot_guided_people.py). A clause of time ("until the robot leads
her") keeps their wait (tests/language/test_reading_guided_route.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("museum", "A lost child waits in the cafe and the robot leads her to the entrance hall.", "cafe",
     "entrance_hall"),
    ("hospital", "Two confused visitors stand by the lifts, and the robot escorts them to the main entrance.",
     "elevator_hall", "main_entrance"),
    ("station", "An old man has wandered onto platform 2, so the robot guides him back to the ticket office.",
     "platform_2", "ticket_office"),
])
def test_people_the_robot_takes_along_later_follow_it(read, world, prompt, start, destination):
    reading = read(world, prompt)
    (g,) = reading.groups
    assert (g.intent, g.robot_interaction, g.start, g.destination) == ("robot", "follow", start, destination)
    assert reading.robot is not None and (reading.robot.start, reading.robot.destination) == (start, destination)
