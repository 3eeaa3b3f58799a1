"""A robot word inside a place's name ("the robot lab", "the robot arena") names the place, not the robot
(robot_place_names.py)."""

from __future__ import annotations


def test_walking_to_the_robot_lab_is_a_walk_not_a_robot_encounter(read):
    (group,) = read("university", "Three first-years wander over from the library to the robot lab.").groups
    assert (group.intent, group.destination) == ("walk", "robotics_lab")
    assert group.robot_interaction is None


def test_the_robot_still_heard_beside_a_robot_worded_place(read):
    reading = read("university", "A postdoc waits in the robot arena while the robot patrols the corridor.")
    (group,) = reading.groups
    assert group.location in ("robotics_lab", "test_arena") and reading.robot is not None
