"""Blocking the robot at a place: "a steward blocks the robot at the rinkside". The block claim had no place
and BlockRobot sent the steward to the robot wherever it was; now the steward holds a post where the robot
passes the rinkside, blocks it there, and the report checks the block at the rinkside. Without a place the
block is as before. Planned from hand-written drafts (no model), one real simulation, and the export."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
import shapely
import yaml
from helpers.planned_run import plan_by_hand

from grove_tui.exports.hunav import export_hunav
from grove_tui.generation.block_at_place import HOLD_RADIUS
from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.world import load_world

RINK = "eval/understanding/worlds/ice_rink.yaml"
STEWARD = "A steward blocks the robot at the rinkside while the robot drives from the entrance to the cafe."


@pytest.fixture(scope="module")
def steward(tmp_path_factory):
    world = load_world(RINK)
    return world, plan_by_hand(world, "normal", STEWARD, (DraftGroup("steward", 1, "concourse",
                                                                      DraftNode("BlockRobot", {})),),
                               tmp_path_factory.mktemp("steward") / "b")


def _post(xml: str) -> tuple[float, float]:
    from grove_tui.bt.format.xml import read_tree
    check = next(e for e in read_tree(xml, "t").nodes() if e.id == "IsAtPosition")
    return float(check.get("target_x")), float(check.get("target_y"))


def test_the_claim_and_the_tree_hold_the_place(steward):
    world, run = steward
    claim = next(c for g in run.report.groups for c in g.claims if c.kind == "robot_block")
    assert claim.zone == "rinkside" and "rinkside" in claim.asked, claim
    post = _post((run.bundle / run.op.agents[0].tree).read_text(encoding="utf-8"))
    assert shapely.contains_xy(world.zone("rinkside").polygon, *post)
    # on the robot's way there
    route = shapely.LineString(run.op.robot.path)
    assert route.distance(shapely.Point(post)) < 1.0


def test_the_steward_blocks_the_robot_there_and_keeps_the_post(steward):
    world, run = steward
    report = run.run(120.0)
    claim = next(c for g in report.groups for c in g.claims if c.kind == "robot_block")
    assert claim.status == "holds", claim.evidence
    post = _post((run.bundle / run.op.agents[0].tree).read_text(encoding="utf-8"))
    frames = pd.read_csv(run.bundle / "trajectories.csv")
    person = frames[frames.id == run.op.agents[0].id]
    robot = frames[frames.id == 0].set_index("frame")
    near_post = person[np.hypot(person.x - post[0], person.y - post[1]) <= HOLD_RADIUS + 0.8]
    # there from when they reached it: never off after the robot wherever it goes
    first = near_post.t.min()
    later = person[person.t >= first]
    assert np.hypot(later.x - post[0], later.y - post[1]).max() <= HOLD_RADIUS + 1.0
    # the robot did come within reach of the post and stood slowed there
    joined = later.set_index("frame").join(robot, rsuffix="_robot", how="inner")
    slowed = joined[np.hypot(joined.vx_robot, joined.vy_robot) < 0.4]
    assert len(slowed) and np.hypot(slowed.x_robot - post[0], slowed.y_robot - post[1]).min() < 3.0


def test_without_a_place_the_block_is_as_before(tmp_path):
    world = load_world("hospital")
    run = plan_by_hand(world, "normal", "A nurse blocks the robot while the robot drives to the cafeteria.",
                       (DraftGroup("nurse", 1, "main_corridor", DraftNode("BlockRobot", {})),), tmp_path / "b")
    claim = next(c for g in run.report.groups for c in g.claims if c.kind == "robot_block")
    assert claim.zone is None and claim.point is None
    xml = (run.bundle / run.op.agents[0].tree).read_text(encoding="utf-8")
    assert "<BlockRobot" in xml and "IsAtPosition" not in xml


def test_the_export_knows_the_post_by_its_goal_id(steward, tmp_path):
    _, run = steward
    post = _post((run.bundle / run.op.agents[0].tree).read_text(encoding="utf-8"))
    out = export_hunav(run.bundle, tmp_path / "hunav")
    goals = yaml.safe_load(out.agents_yaml.read_text())["hunav_loader"]["ros__parameters"]["global_goals"]
    from grove_tui.bt.format.xml import read_tree
    xml = next(p for p in out.trees if "agent_1_" in p.name).read_text()
    check = next(e for e in read_tree(xml, "x").nodes() if e.id == "IsAtPosition")
    goal = goals[int(check.get("goal_id"))]
    assert math.dist((goal["x"], goal["y"]), post) < 0.01


DESK = "The receptionist at the reception desk blocks the robot as it leaves reception for the boardroom"


def test_a_robot_that_sets_off_by_the_desk_passes_it_and_is_blocked_there(tmp_path):
    """The robot starts by the reception desk: its route passes the desk in its first metres. The check
    skipped the route's first 5 m, so the report noted "the robot's route does not pass reception_desk",
    which the run contradicts, and the receptionist stayed behind the desk. Passing is measured on the
    whole route: the receptionist holds a post on it and the run shows the block."""
    world = load_world("worlds/office.yaml")
    run = plan_by_hand(world, "normal", DESK, (DraftGroup("receptionist", 1, "reception", DraftNode("BlockRobot", {})),),
                       tmp_path / "b")
    assert not any("does not pass reception_desk" in n for n in run.report.repairs), run.report.repairs
    assert run.op.robot is not None
    start = run.op.robot.path[0]
    desk = world.find("reception_desk").interaction_point
    assert math.dist(start, desk) < 5.0  # the robot does set off by the desk
    checked = run.run(40.0)
    block = next(c for c in checked.groups[0].claims if c.kind == "robot_block")
    assert block.status == "holds", block.evidence
