"""The robot's own clause kept beside the people's (language/robot_typos.py): a bare "bot" opening a chat
clause ("bot on standby @ the front desk, ...") is the robot, not a verb, so it waits there and the people
after the comma keep their own reading; a fronted "While the robot ferries X to Y, ..." keeps the robot's
errand and the group's place."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,location", [
    ("office", "bot on standby @ the front desk, 3 interns staring at it from the kitchen", "reception_desk"),
    ("office", "bot idle by the printer, 2 devs chatting in the kitchen", "printer"),
    ("hospital", "Bot parked at the pharmacy; a porter waits in the corridor", "pharmacy"),
])
def test_a_bare_bot_opening_a_chat_clause_is_the_robot_waiting(read, world, prompt, location):
    reading = read(world, prompt)
    assert reading.robot is not None and (reading.robot.task, reading.robot.location) == ("wait", location)
    assert len(reading.groups) == 1 and reading.groups[0].count.kind == "exact"


def test_people_staring_at_a_robot_on_standby_look_at_it(read):
    group = read("office", "bot on standby @ the front desk, 3 interns staring at it from the kitchen").groups[0]
    assert group.count.value == 3 and group.robot_interaction == "look"


@pytest.mark.parametrize("world,prompt,destination,location", [
    ("hospital", "While the robot ferries trays to ward B, a family of four waits in reception.", "ward_b",
     "reception_desk"),
    ("hospital", "While the bot trundles dirty cups back to the cafeteria, three visitors sit in the waiting room.",
     "cafeteria", "main_waiting_room"),
])
def test_a_fronted_robot_errand_keeps_both_clauses(read, world, prompt, destination, location):
    reading = read(world, prompt)
    assert reading.robot is not None and (reading.robot.task, reading.robot.destination) == ("cross", destination)
    assert len(reading.groups) == 1 and reading.groups[0].location == location
