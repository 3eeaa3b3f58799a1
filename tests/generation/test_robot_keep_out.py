"""The robot kept out of a place by its clause ("drives from radiology to the pharmacy, avoiding the main
waiting room"): its path goes round it where the shortest one would cross it, its row carries a keep_out
claim the run earns (its trajectory never enters the place), and a robot that does enter is ✗
(generation/robot_keep_out.py, analysis/outcomes.py `_RobotKeepOutProbe`). Real reader, planner and
simulation; the people are planned from a hand-written draft."""

from __future__ import annotations

import shapely
from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.generation.keep_out import keep_out_planner
from grove_tui.generation.robot_keep_out import robot_keep_out_claim
from grove_tui.navigation.grid import build_grid
from grove_tui.navigation.theta_star import ThetaStarPlanner
from grove_tui.scenario.report import FAILS, HOLDS, PLANNED, Claim, GroundingReport, RobotGrounding

AVOIDING = "The robot drives from radiology to the pharmacy, avoiding the main waiting room."
STRAIGHT = "The robot drives from radiology to the pharmacy."
VISITORS = (DraftGroup("visitors", 2, "ward_b", DraftNode("Wait", {"duration": 5.0})),)


def _inside(world, name):
    return world.zone(name).polygon.buffer(-0.3)


def test_the_robots_path_goes_round_the_room_the_straight_one_crosses_and_the_run_keeps_out(hospital, tmp_path):
    run = plan_by_hand(hospital, "normal", AVOIDING, VISITORS, tmp_path / "b")
    robot = run.op.robot
    assert robot is not None
    waiting = _inside(hospital, "main_waiting_room")
    straight = ThetaStarPlanner(build_grid(hospital)).plan(robot.start, robot.goal)
    assert shapely.LineString(straight).intersects(waiting)  # the shortest way is through it
    assert not shapely.LineString(robot.path).intersects(waiting)
    (keep,) = [c for c in run.report.robot.claims if c.kind == "keep_out"]
    assert keep.status == PLANNED and keep.place == "main_waiting_room"
    checked = run.run(75.0)
    (kept,) = [c for c in checked.robot.claims if c.kind == "keep_out"]
    assert kept.status == HOLDS, kept.evidence
    reach = next(c for c in checked.robot.claims if c.kind == "robot_reach" and c.asked == "pharmacy")
    assert reach.status == HOLDS, reach.evidence  # it still gets there


def test_a_robot_that_drives_through_the_room_is_a_cross(hospital, tmp_path):
    """The path forced through: the sentence without the avoid planned and run, its report checked with
    the keep_out claim the avoiding sentence would carry."""
    run = plan_by_hand(hospital, "normal", STRAIGHT, VISITORS, tmp_path / "b")
    robot = run.op.robot
    assert robot is not None and shapely.LineString(robot.path).intersects(_inside(hospital, "main_waiting_room"))
    keep = Claim("keep_out", "main_waiting_room", "drive round main_waiting_room", zone="main_waiting_room",
                 place="main_waiting_room", share=1.0, needs_seconds=30.0)
    planned = GroundingReport(run.report.prompt, run.report.groups, robot=RobotGrounding(
        "cross", STRAIGHT, (*run.report.robot.claims, keep), run.report.robot.plan))
    run.run(45.0)
    checked = run.check(planned, hospital)
    (kept,) = [c for c in checked.robot.claims if c.kind == "keep_out"]
    assert kept.status == FAILS and kept.mark == "✗"
    assert "the robot was in main_waiting_room at t =" in kept.evidence
    # and the plan itself says so before any run: its path goes through the room
    said = robot_keep_out_claim(keep, hospital, [tuple(p) for p in robot.path], 30.0)
    assert said.status == FAILS and "goes through main_waiting_room" in said.evidence


def test_a_start_inside_the_place_is_said_not_hidden(hospital):
    keep = Claim("keep_out", "cafeteria", "plan round cafeteria", zone="cafeteria", place="cafeteria")
    start = hospital.zone("cafeteria").centroid
    said = robot_keep_out_claim(keep, hospital, [start, hospital.zone("pharmacy").centroid], 20.0)
    assert said.status == FAILS and "starts in cafeteria" in said.evidence


def test_with_no_way_round_the_robot_goes_through_and_the_notes_and_the_claim_say_so(clinic, tmp_path):
    assert keep_out_planner(clinic, build_grid(clinic), ["corridor"]) is not None
    run = plan_by_hand(clinic, "normal", "The robot drives from the lobby to the cafeteria, avoiding the corridor.",
                       (DraftGroup("visitors", 2, "lobby", DraftNode("Wait", {"duration": 5.0})),), tmp_path / "b")
    assert any("corridor" in n and "keeps out of" in n for n in run.op.notes), run.op.notes
    (keep,) = [c for c in run.report.robot.claims if c.kind == "keep_out"]
    assert keep.status == FAILS and "corridor" in keep.evidence
