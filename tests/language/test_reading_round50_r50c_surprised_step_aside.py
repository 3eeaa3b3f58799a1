"""Round 50 (r50c): a start of surprise when the robot passes, then a step out of its way ("jumps in
surprise when the robot rolls past and hops out of its way") is a surprised step aside (avoid,
Surprised): the verb after the robot's "and" that goes out of its way is the person's
(robot_passed_by.py), and a wall named after a preposition walls nobody in (robot_idioms.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,location", [
    ("mall", "A shopper at the fountain jumps in surprise when the robot rolls past and hops out of its way.",
     "fountain"),
    ("museum", "A guide near the gift shop wall flinches in astonishment as the robot trundles past and backs "
     "away from it.", "gift_shop"),
])
def test_a_step_out_of_its_way_after_the_robot_passes_is_the_persons(read, world, prompt, location):
    reading = read(world, prompt)
    group = reading.groups[0]
    assert (group.robot_interaction, group.robot_reaction, group.location) == ("avoid", "Surprised", location)
    assert "way" not in reading.robot.text and "away" not in reading.robot.text


@pytest.mark.parametrize("world,prompt", [
    ("tennis_club", "A junior at the practice wall jumps in surprise when the robot rolls past."),
    ("hospital", "A porter by the lobby wall gasps in surprise as the robot glides by."),
])
def test_a_wall_after_a_preposition_is_no_walling_in(read, world, prompt):
    group = read(world, prompt).groups[0]
    assert group.robot_interaction == "look"
