"""Operational layer: waypoints keep every leg collision-free, fields lead groups out, the robot crosses the scene."""

from __future__ import annotations

import math

import pytest
from lxml import etree

from grove_tui.generation.draft import Draft, DraftGroup, DraftNode
from grove_tui.navigation.theta_star import ThetaStarPlanner
from grove_tui.bt.format.xml import write_tree
from grove_tui.generation.planning import RobotRequest, goals_from_tree, plan_operational
from grove_tui.generation.postprocess import postprocess
from grove_tui.generation.presets import GenerationError, load_preset
from grove_tui.language.reading import read_prompt
from grove_tui.generation.rois import select_rois


def plan(clinic, grid, preset_name, prompt, groups, robot=None, seed=0):
    preset = load_preset(preset_name)
    reading = read_prompt(prompt, clinic, seed=seed)
    selection = select_rois(clinic, preset, reading)
    post = postprocess(clinic, grid, preset, Draft(tuple(groups)), selection, seed, reading,
                       ("Sequence", "GoTo", "Queue", "FollowVelocityField", "Wait", "JoinGroup"))
    return post, plan_operational(clinic, grid, preset, post, seed, robot)


def free_path(grid, points):
    planner = ThetaStarPlanner(grid)
    return all(planner.segment_is_free(a[0], a[1], b[0], b[1]) for a, b in zip(points, points[1:]))


def test_waypoints_make_every_leg_collision_free(clinic, grid):
    tree = DraftNode("Sequence", {}, (DraftNode("GoTo", {"target": "cafeteria"}), DraftNode("GoTo", {"target": "pharmacy"})))
    post, op = plan(clinic, grid, "normal", "Five visitors walk from the lobby to the cafeteria and then the pharmacy",
                    [DraftGroup("visitors", 5, "lobby", tree)])
    for agent in op.agents:
        xml = write_tree(op.trees[agent.tree])
        gotos = etree.fromstring(xml.encode()).findall(".//GoTo")
        assert all(g.get("waypoints") for g in gotos)  # lobby -> cafeteria cannot be a straight line
        assert free_path(grid, [agent.start, *agent.goals])
        assert agent.goals == tuple(goals_from_tree(op.trees[agent.tree]))
        assert clinic.zone("pharmacy").polygon.contains(__import__("shapely").Point(agent.goals[-1]))
        assert agent.zone == "pharmacy"


def test_emergency_builds_one_field_per_group_toward_its_exit(clinic, grid):
    groups = [DraftGroup("diners", 6, "cafeteria", DraftNode("FollowVelocityField", {"exit": "main_entrance"})),
              DraftGroup("patients", 4, "pharmacy", DraftNode("FollowVelocityField", {"exit": "main_entrance"}))]
    post, op = plan(clinic, grid, "emergency", "Six diners in the cafeteria and four patients in the pharmacy evacuate",
                    groups)
    assert set(op.fields) == {"group_1", "group_2"}
    for fid, field in op.fields.items():
        members = [a for a in op.agents if etree.fromstring(write_tree(op.trees[a.tree]).encode()).find(".//FollowVelocityField").get("field") == fid]
        assert members
        exits = {etree.fromstring(write_tree(op.trees[a.tree]).encode()).find(".//FollowVelocityField").get("exit") for a in members}
        assert len(exits) == 1 and field.exit == clinic.find(exits.pop()).position
        for a in members:
            vx, vy = field.sample(*a.start)
            assert math.hypot(vx, vy) > 0.5  # every spawn has a direction to follow
            assert a.goals[-1] == tuple(round(v, 3) for v in field.path[-1])


def test_robot_is_chosen_across_the_crowd_and_planned(clinic, grid):
    post, op = plan(clinic, grid, "normal", "Eight visitors wait in the lobby",
                    [DraftGroup("visitors", 8, "lobby", DraftNode("Wait", {"duration": 30.0}))])
    robot = op.robot
    assert robot is not None and len(robot.path) >= 2
    assert robot.path[0] == robot.start and robot.path[-1] == robot.goal
    assert all(math.dist(robot.start, a.start) >= 2.0 and math.dist(robot.goal, a.start) >= 2.0 for a in op.agents)
    assert free_path(grid, list(robot.path))
    assert math.dist(robot.start, robot.goal) >= 4.0


def test_robot_start_and_goal_from_the_user(clinic, grid):
    request = RobotRequest(start="main_entrance", goal=(17.0, -3.0))
    post, op = plan(clinic, grid, "normal", "Eight visitors wait in the lobby",
                    [DraftGroup("visitors", 8, "lobby", DraftNode("Wait", {"duration": 30.0}))], robot=request)
    assert op.robot.start == pytest.approx(clinic.find("main_entrance").inward_point(0.8), abs=0.15)
    assert op.robot.goal == (17.0, -3.0)
    _, op = plan(clinic, grid, "normal", "Eight visitors wait in the lobby",
                 [DraftGroup("visitors", 8, "lobby", DraftNode("Wait", {"duration": 30.0}))],
                 robot=RobotRequest(enabled=False))
    assert op.robot is None


def test_robot_goal_on_a_wall_is_refused(clinic, grid):
    with pytest.raises(GenerationError, match="robot goal"):
        plan(clinic, grid, "normal", "Eight visitors wait in the lobby",
             [DraftGroup("visitors", 8, "lobby", DraftNode("Wait", {"duration": 30.0}))],
             robot=RobotRequest(start=(5.0, 3.0), goal=(60.0, 60.0)))
