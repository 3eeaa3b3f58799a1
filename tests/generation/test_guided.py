"""A robot that guides people goes where they go (generation/guided.py): "the passengers evacuate
while the robot guides them to the exit" sends the robot to the passengers' exit, whatever place a
model picked for "the exit" alone, and the report claims that they went with it."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from grove_tui.generation.draft import Draft, DraftGroup, DraftNode
from grove_tui.generation.guided import guided_index
from grove_tui.generation.planning import plan_operational
from grove_tui.generation.postprocess import postprocess
from grove_tui.generation.presets import load_preset
from grove_tui.generation.reconcile import grounding_report
from grove_tui.generation.rois import select_rois
from grove_tui.language.reading import read_prompt
from grove_tui.navigation.grid import build_grid
from grove_tui.world import load_world

FERRY = Path(__file__).resolve().parents[2] / "eval/understanding/worlds/ferry_terminal.yaml"
PROMPT = "A fire alarm goes off and the passengers in the waiting lounge evacuate while the robot guides them to the exit"
LEAVE = DraftNode("Sequence", {}, (DraftNode("FollowVelocityField", {"exit": "main_entrance"}),))


@pytest.fixture(scope="module")
def ferry():
    return load_world(FERRY)


def test_the_robot_guiding_evacuees_goes_to_their_exit_and_the_report_says_they_go_with_it(ferry):
    reading = read_prompt(PROMPT, ferry)
    assert reading.robot is not None and reading.robot.guides == reading.groups[0].who and guided_index(reading) == 0
    # the roi model may settle the unsure "the exit" on a door the passengers do not use
    reading = replace(reading, robot=replace(reading.robot, destination="staff_entrance"))
    preset = load_preset("emergency")
    grid = build_grid(ferry)
    post = postprocess(ferry, grid, preset, Draft((DraftGroup("passengers", 4, "departure_lounge", LEAVE),)),
                       select_rois(ferry, preset, reading), 0, reading, ("Sequence", "FollowVelocityField"))
    exits = {a.exit for a in post.agents}
    assert len(exits) == 1 and "staff_entrance" not in exits
    op = plan_operational(ferry, grid, preset, post, 0, reading=reading)
    door = ferry.find(exits.pop())
    assert abs(op.robot.goal[0] - door.position[0]) + abs(op.robot.goal[1] - door.position[1]) < 3.0
    report = grounding_report(reading, post.groups, post.agents, ferry, post.notes + op.notes, robot=op.robot)
    assert report.robot is not None
    assert [c.place for c in report.robot.claims if c.kind == "robot_reach"] == [door.name]
    assert [c.kind for c in report.groups[0].claims].count("robot_follow") == 1


def test_people_guided_by_name_are_that_group_and_nobody_guided_is_none(ferry):
    named = read_prompt("Six passengers wait at the cafe while the robot escorts two children to the check-in hall",
                        ferry)
    assert named.robot is not None and guided_index(named) == next(
        i for i, g in enumerate(named.groups) if "children" in g.who)
    alone = read_prompt("Six passengers wait at the cafe while the robot drives to the check-in hall", ferry)
    assert guided_index(alone) is None
