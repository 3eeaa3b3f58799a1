"""Round 35 (r35robot): the robot's own task when people go with it. People who walk with the robot,
go along with it or accompany it follow it, and the robot crosses to where they go."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,destination", [
    ("hospital", "A porter strolls with the robot to the cafeteria.", "cafeteria"),
    ("hospital", "An old man goes along with the robot to the pharmacy.", "pharmacy"),
    ("museum", "Two children walk alongside the robot to the cafe.", "cafe"),
    ("museum", "Three visitors come with the robot to the cafe.", "cafe"),
    ("library", "A student walks with the robot to the reading room.", "reading_room"),
    ("library", "Two students accompany the robot to the issue desk.", "issue_desk"),
    ("office", "The robot is accompanied by an intern to the boardroom.", "boardroom"),
])
def test_people_who_go_with_the_robot_follow_it_there(read, world, prompt, destination):
    r = read(world, prompt)
    assert len(r.groups) == 1, r.groups
    assert r.groups[0].robot_interaction == "follow", r.groups[0]
    assert r.robot is not None and r.robot.task == "cross" and r.robot.destination == destination, r.robot


@pytest.mark.parametrize("world,prompt,interaction", [
    ("museum", "A guide walks with her group to the cafe while the robot waits in the lobby.", None),
    ("hospital", "Two visitors follow the robot to the cafeteria.", "follow"),
    ("hospital", "A nurse walks to the pharmacy with a patient.", None),
    ("hospital", "The robot is followed by a nurse to the pharmacy.", "follow"),
])
def test_guard_going_with_someone_else_or_following(read, world, prompt, interaction):
    r = read(world, prompt)
    assert r.groups[0].robot_interaction == interaction, r.groups


@pytest.mark.parametrize("world,prompt", [
    ("office", "During the drill the robot leads the interns out of the building."),
    ("office", "The robot ushers two visitors out of the premises."),
    ("museum", "The robot guides the school party out of the museum."),
    ("museum", "The robot escorts an elderly couple out of the whole building."),
    ("airport", "Ten passengers panic while the robot leads them out of the building."),
    ("hospital", "The robot guides three visitors out of the hospital."),
])
def test_the_robot_leading_people_out_of_the_building_goes_to_an_exit(read, worlds, world, prompt):
    robot = read(world, prompt).robot
    assert robot is not None and robot.task == "cross", robot
    assert robot.destination in {door.name for door in worlds[world].exits()}, robot


@pytest.mark.parametrize("world,prompt,destination", [
    ("office", "The robot leads the interns out of the kitchen to the boardroom.", "boardroom"),
    ("museum", "The robot guides the visitors to the cafe.", "cafe"),
])
def test_guard_leading_out_of_a_named_place_keeps_its_route(read, world, prompt, destination):
    robot = read(world, prompt).robot
    assert robot is not None and robot.destination == destination, robot
