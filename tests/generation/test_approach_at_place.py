"""Approaching the robot at a place: "three children in the playground approach the robot". The approach claim
had no place and ApproachRobot sent the children after the robot from the first second, wherever it was: they
met it in the library, after it had arrived, and the report gave ✓. Now they wait in the playground beside the
robot's route (which goes through the playground), come up to it when it is near, and the report checks the
meeting in the playground. Without a place the approach is as before. Hand-written drafts, one simulation."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
import shapely
from helpers.planned_run import plan_by_hand

from grove_tui.generation.approach_at_place import HOLD_RADIUS
from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.world import load_world

SCHOOL = "eval/understanding/worlds/primary_school.yaml"
CHILDREN = "Three children in the playground approach the robot while it drives from the dining hall to the library."


def _approach(report):
    return next(c for g in report.groups for c in g.claims if c.kind == "robot_approach")


def _post(run, agent):
    from grove_tui.bt.format.xml import read_tree
    xml = (run.bundle / agent.tree).read_text(encoding="utf-8")
    check = next(e for e in read_tree(xml, "t").nodes() if e.id == "IsAtPosition")
    return float(check.get("target_x")), float(check.get("target_y"))


@pytest.fixture(scope="module")
def children(tmp_path_factory):
    world = load_world(SCHOOL)
    return world, plan_by_hand(world, "normal", CHILDREN, (DraftGroup("child", 3, "playground",
                                                                      DraftNode("ApproachRobot", {})),),
                               tmp_path_factory.mktemp("children") / "b")


def test_the_claim_the_posts_and_the_route_are_at_the_place(children):
    world, run = children
    claim = _approach(run.report)
    assert claim.zone == "playground" and "playground" in claim.asked, claim
    playground = world.zone("playground").polygon
    route = shapely.LineString(run.op.robot.path)
    assert route.intersection(playground).length > 1.0  # the robot comes through the playground
    for agent in run.op.agents:
        post = _post(run, agent)
        assert shapely.contains_xy(playground, *post)
        assert 1.5 < route.distance(shapely.Point(post)) < 5.0  # beside its way, not on it


def test_they_wait_there_and_meet_the_robot_in_the_playground(children):
    world, run = children
    report = run.run(120.0)
    claim = _approach(report)
    assert claim.status == "holds", claim.evidence
    frames = pd.read_csv(run.bundle / "trajectories.csv")
    robot = frames[frames.id == 0].set_index("frame")
    playground = world.zone("playground").polygon
    for agent in run.op.agents:
        person = frames[frames.id == agent.id].set_index("frame").join(robot, rsuffix="_robot", how="inner")
        gap = np.hypot(person.x - person.x_robot, person.y - person.y_robot)
        met = person[gap <= 2.5]
        assert len(met) and shapely.contains_xy(playground, met.x.to_numpy(), met.y.to_numpy()).any()
        # never off after the robot beyond their hold of the post
        post = _post(run, agent)
        there = person[np.hypot(person.x - post[0], person.y - post[1]) <= 1.0]
        later = person.loc[there.index.min():]
        assert np.hypot(later.x - post[0], later.y - post[1]).max() <= HOLD_RADIUS + 1.5


def test_a_place_where_they_start_is_the_place(tmp_path):
    world = load_world("worlds/airport.yaml")
    run = plan_by_hand(world, "normal", "Two kids at the duty free run up to the robot as it drives from the "
                       "check in hall to gate b1.", (DraftGroup("kid", 2, "duty_free", DraftNode("ApproachRobot", {})),),
                       tmp_path / "b")
    claim = _approach(run.report)
    assert claim.zone == "duty_free", claim
    xml = (run.bundle / run.op.agents[0].tree).read_text(encoding="utf-8")
    assert "IsAtPosition" in xml and 'max_vel="1.82"' in xml  # running: at their pace


def test_without_a_place_the_approach_is_as_before(tmp_path):
    world = load_world("hospital")
    run = plan_by_hand(world, "normal", "A nurse approaches the robot while the robot drives to the cafeteria.",
                       (DraftGroup("nurse", 1, "main_corridor", DraftNode("ApproachRobot", {})),), tmp_path / "b")
    claim = _approach(run.report)
    assert claim.zone is None and claim.point is None
    xml = (run.bundle / run.op.agents[0].tree).read_text(encoding="utf-8")
    assert "<ApproachRobot" in xml and "IsAtPosition" not in xml
