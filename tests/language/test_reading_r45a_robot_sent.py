"""Round 45: the robot sent somewhere in the passive ("the robot was dispatched to ICU", "the bot gets
directed over to the ticket office") crosses there; the people of the other clause keep their place."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, destination, where", [
    ("hospital", "The robot was dispatched to ICU while two nurses wait at the pharmacy.", "intensive_care", "pharmacy"),
    ("station", "Three guards stand at the gateline; the bot gets directed over to the ticket office.", "ticket_office",
     "gateline"),
])
def test_the_robot_sent_in_the_passive_crosses(read, world, prompt, destination, where):
    reading = read(world, prompt)
    assert (reading.robot.task, reading.robot.destination) == ("cross", destination)
    assert [g.location for g in reading.groups] == [where]


def test_a_person_sent_is_no_robot(read):
    reading = read("hospital", "A porter is sent from the pharmacy to ICU.")
    assert reading.robot is None or reading.robot.task != "cross"
