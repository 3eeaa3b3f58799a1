"""People who only react to the robot at a door or a thing ("a porter stands at the hotel entrance and greets
the robot") have the robot come by that place. Before, the robot's route crossed the lobby (the entrance's
zone, so no room was "missed") 8 m from the door, the porter's post stayed at the door and the approach was
a true ✗ at 7.9 m."""

from __future__ import annotations

import math

from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.scenario.report import HOLDS
from grove_tui.world import load_world

HOTEL = "eval/understanding/worlds/hotel.yaml"
SENTENCE = "A porter stands at the hotel entrance and greets the robot"


def test_the_robot_passes_the_porter_at_the_entrance_and_the_greeting_holds(tmp_path):
    hotel = load_world(HOTEL)
    run = plan_by_hand(hotel, "normal", SENTENCE,
                       (DraftGroup("porter", 1, "lobby", DraftNode("ApproachRobot", {"duration": 5.0})),),
                       tmp_path / "b")
    door = hotel.find("main_entrance").position
    route = run.op.robot.path or (run.op.robot.start, run.op.robot.goal)
    assert min(math.dist(p, door) for p in route) < 4.0, route
    claim = next(c for c in run.report.groups[0].claims if c.kind == "robot_approach")
    report = run.run(claim.needs_seconds or 120.0)
    checked = next(c for c in report.groups[0].claims if c.kind == "robot_approach")
    assert checked.status == HOLDS, checked.evidence
