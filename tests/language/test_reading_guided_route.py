"""The robot that guides people its own clause gives no place: it goes where they go, from where they
start ("... walk to the exit while the robot guides them"); a clause opened by "until" / "till" is the
robot's own ("waits at the desk until the robot leads her to check-in"). Real spaCy, real worlds."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt


@pytest.mark.parametrize("world, prompt, start, destination, guided", [
    ("airport", "Ten passengers at gate B1 walk to the exit while the robot guides them.", "gate_b1", None, "passengers"),
    ("hospital", "Two visitors walk from the main entrance to the cafeteria and the robot guides them.",
     "main_entrance", "cafeteria", "visitors"),
    ("museum", "A school group heads from the main entrance to the cafe while the robot leads them.",
     "main_entrance", "cafe", "school group"),
    ("office", "Three interns go from reception to the large meeting room, and the robot escorts them.",
     "reception", None, "interns"),
])
def test_the_robot_goes_where_the_people_it_guides_go(worlds, world, prompt, start, destination, guided):
    reading = read_prompt(prompt, worlds[world], seed=0)
    robot = reading.robot
    assert robot is not None and robot.task == "cross", robot
    assert robot.start == start
    group = reading.groups[0]
    assert robot.destination == group.destination and robot.destination is not None
    if destination is not None:
        assert robot.destination == destination
    assert robot.guides is not None and guided in robot.guides.lower()


@pytest.mark.parametrize("world, prompt, destination, pronoun", [
    ("airport", "A lost child waits at the information desk until the robot leads her to the check-in area.",
     "check_in_hall", "her"),
    ("station", "An elderly man waits on platform 1 till the robot guides him to the ticket office.",
     "ticket_office", "him"),
])
def test_a_clause_opened_by_until_is_the_robots_own(worlds, world, prompt, destination, pronoun):
    reading = read_prompt(prompt, worlds[world], seed=0)
    assert reading.robot is not None and reading.robot.task == "cross"
    assert reading.robot.destination == destination
    assert reading.robot.guides == pronoun
    assert len(reading.groups) == 1 and reading.groups[0].intent == "wait"
    assert reading.groups[0].destination is None  # the robot's place is not the person's


@pytest.mark.parametrize("world, prompt", [
    ("station", "A family sits on a bench on platform 2 while the robot guides them."),
    ("airport", "A family sits at gate B1 while the robot guides them."),
])
def test_people_going_nowhere_give_the_robot_no_route(worlds, world, prompt):
    assert read_prompt(prompt, worlds[world], seed=0).robot is None


def test_a_robot_that_only_arrives_until_which_people_work_is_no_task(worlds):
    reading = read_prompt("Two cleaners mop the check-in hall until the robot arrives.", worlds["airport"], seed=0)
    assert reading.robot is None
    assert reading.groups[0].location == "check_in_hall"
