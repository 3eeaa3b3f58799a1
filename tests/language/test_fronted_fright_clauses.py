"""A fright fronted with the robot's own clause before the subject ("Rattled when the robot beeps, two
cleaners hurry out of X"): the subject avoids the robot, Scared (fronted_fright_clauses.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count", [
    ("hospital", "Rattled when the robot beeps, two cleaners hurry out of the staff room.", 2),
    ("mall", "Nervous as the robot glides past, an old man shuffles off towards the food court.", 1),
    ("underground_station", "Frightened the moment the robot trundles in, four schoolboys dash out of the mess.", 4),
])
def test_a_fronted_fright_with_the_robots_clause_is_a_scared_avoidance(read, world, prompt, count):
    group = read(world, prompt).groups[0]
    assert group.count.value == count
    assert (group.intent, group.robot_interaction, group.robot_reaction) == ("robot", "avoid", "Scared")


def test_a_fronted_clause_without_a_fright_is_no_reaction(read):
    group = read("hospital", "Busy as the robot beeps, two cleaners hurry out of the staff room.").groups[0]
    assert group.robot_reaction is None
