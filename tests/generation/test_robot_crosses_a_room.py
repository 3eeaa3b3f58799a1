""""The robot crosses the main waiting room" names no place to go. The robot used to set off from the
room's middle (its anchor) and leave by the nearest door: half a crossing, and the report's robot_via
was ✓ at t = 0.1 s because it started inside. Now it sets off by the far wall and leaves by the door
across the room, and the report checks a crossing (from one edge of the room to another), so setting
off from the middle is ✗."""

from __future__ import annotations

import numpy as np
import pandas as pd
import shapely
from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.scenario.report import FAILS, HOLDS
from grove_tui.world import load_world

SENTENCE = "the robot crosses the main waiting room while four visitors look at it"


def test_the_robot_crosses_the_room_from_wall_to_door_and_the_report_checks_a_crossing(tmp_path):
    hospital = load_world("hospital")
    groups = (DraftGroup("visitors", 4, "entrance_lobby", DraftNode("LookAtRobot", {})),)
    run = plan_by_hand(hospital, "normal", SENTENCE, groups, tmp_path / "b")
    room = hospital.zone("main_waiting_room").polygon
    start = run.op.robot.start
    assert room.contains(shapely.Point(start))
    assert room.boundary.distance(shapely.Point(start)) <= 3.0, start  # by a wall, not the room's middle
    assert not room.contains(shapely.Point(run.op.robot.goal))  # and out of the room
    report = run.run(60.0)
    via = next(c for c in report.robot.claims if c.kind == "robot_via")
    assert via.status == HOLDS, via.evidence


def test_a_robot_setting_off_from_the_middle_of_the_room_has_not_crossed_it(tmp_path):
    hospital = load_world("hospital")
    groups = (DraftGroup("visitors", 4, "entrance_lobby", DraftNode("LookAtRobot", {})),)
    run = plan_by_hand(hospital, "normal", SENTENCE, groups, tmp_path / "b")
    run.run(60.0)
    # the same run's frames, with the robot's track moved to start in the room's middle and drive out by
    # the lobby door (as the old plan did)
    csv = run.bundle / "trajectories.csv"
    df = pd.read_csv(csv)
    robot = df["id"] == 0
    t = df.loc[robot, "t"].to_numpy()
    x = np.clip(17.9 + 0.8 * t, None, 45.0)
    df.loc[robot, "x"], df.loc[robot, "y"] = x, 8.0
    df.loc[robot, "vx"], df.loc[robot, "vy"], df.loc[robot, "yaw"] = 0.8, 0.0, 0.0
    df.to_csv(csv, index=False)
    checked = run.check(run.report, hospital)
    via = next(c for c in checked.robot.claims if c.kind == "robot_via")
    assert via.status == FAILS, via.evidence
    assert "from its edge" in via.evidence


def test_crossing_a_hall_to_a_far_goal_sets_off_by_the_wall_across_from_it(tmp_path):
    # the goal (a platform) is far off: 80 % as far as the farthest point of the hall was most of the
    # hall, and the robot set off from its middle (5.3 m from any wall of a 12 m hall) to the opening
    station = load_world("station")
    prompt = "twelve travellers queue at the ticket office while a robot crosses the ticket hall to the platforms"
    groups = (DraftGroup("travellers", 12, "ticket_hall", DraftNode("Queue", {"service_point": "ticket_office"})),)
    run = plan_by_hand(station, "queuing", prompt, groups, tmp_path / "b")
    hall = station.zone("ticket_hall").polygon
    start = shapely.Point(run.op.robot.start)
    assert hall.contains(start) and hall.boundary.distance(start) <= 3.0, run.op.robot.start
    report = run.run(90.0)
    via = next(c for c in report.robot.claims if c.kind == "robot_via")
    assert via.status == HOLDS, via.evidence
