"""A robot leading a crowd is not stalled by it ("the robot leads thirty patients to the exit"). Before,
every follower walked at the robot itself: thirty converged on it, some stepped in front, its collision
monitor held it at creep speed and it arrived at 146 s against 48 s planned. Followers of a leading robot
walk to their place behind it (crowd/led_slots.py): it keeps its pace and they arrive with it."""

from __future__ import annotations

import csv
import math

from helpers.planned_run import plan_by_hand

from grove_tui.crowd.led_slots import slot_offset
from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.scenario.report import HOLDS
from grove_tui.world import load_world

SENTENCE = "The robot leads twenty patients to the exit"


def test_followers_take_places_behind_the_robot_in_a_compact_block():
    places = [slot_offset(k, 1.5, 20) for k in range(20)]
    assert all(back >= 1.5 for back, _ in places)
    assert len(set(places)) == 20
    assert max(back for back, _ in places) <= 1.5 + 4 * 0.8 + 1e-9  # 5 rows of 4, not 20 in single file


def test_a_robot_leading_twenty_patients_keeps_its_pace_and_they_arrive_with_it(tmp_path):
    hospital = load_world("worlds/hospital.yaml")
    run = plan_by_hand(hospital, "normal", SENTENCE,
                       (DraftGroup("patients", 20, "main_corridor", DraftNode("Wait", {"duration": 5.0})),),
                       tmp_path / "b", as_the_pipeline=True)
    robot = run.op.robot
    path = list(robot.path or (robot.start, robot.goal))
    planned = sum(math.dist(a, b) for a, b in zip(path, path[1:])) / robot.max_vel
    report = run.run(planned * 2.5)
    arrived = None
    with open(run.bundle / "trajectories.csv") as f:
        for row in csv.DictReader(f):
            if row["id"] == "0" and math.dist((float(row["x"]), float(row["y"])), robot.goal) < 1.0:
                arrived = float(row["t"])
                break
    assert arrived is not None and arrived < 1.35 * planned, (arrived, planned)
    claims = {c.kind: c for c in report.groups[0].claims}
    assert claims["robot_follow"].status == HOLDS, claims["robot_follow"].evidence
    assert claims["reach"].status == HOLDS, claims["reach"].evidence
