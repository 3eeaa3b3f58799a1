"""The robot's route past people who react to it around a routine: "four patients wait in radiology and watch
the robot while the robot drives from the entrance lobby to the cafeteria". Plain reacting groups start beside
the robot's route; people with a routine of their own stayed where it is, and the robot's way passed 18 m from
radiology: they never saw it. Now a crossing robot goes through the zone of such a routine too. A hand-written
draft and a real simulation."""

from __future__ import annotations

import shapely
from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.world import load_world

SENTENCE = "Four patients wait in radiology and watch the robot while the robot drives from the entrance lobby " \
           "to the cafeteria."


def test_the_robot_passes_the_routine_and_they_watch_it(tmp_path):
    world = load_world("worlds/hospital.yaml")
    run = plan_by_hand(world, "normal", SENTENCE, (DraftGroup("patient", 4, "radiology",
                                                              DraftNode("Wait", {"duration": 60})),), tmp_path / "b")
    route = shapely.LineString(run.op.robot.path)
    assert route.intersection(world.zone("radiology").polygon).length > 1.0
    report = run.run(120.0)
    claims = {c.kind: c for g in report.groups for c in g.claims}
    assert claims["robot_look"].status == "holds", claims["robot_look"].evidence
    assert claims["stay"].status == "holds", claims["stay"].evidence
    robot = {c.kind: c for c in report.robot.claims}
    assert robot["robot_reach"].status == "holds", robot


def test_the_robot_passes_where_a_walker_who_reacts_is_going(tmp_path):
    # "the robot never came within 10 m of them": she walked to the staff room, the robot went straight on
    world = load_world("eval/understanding/worlds/primary_school.yaml")
    run = plan_by_hand(world, "normal", "A teacher glances at the robot while she walks to the staff room, and the "
                       "robot drives from the school hall to the library.",
                       (DraftGroup("teacher", 1, "main_corridor", DraftNode("GoTo", {"target": "staff_room"})),),
                       tmp_path / "b")
    route = shapely.LineString(run.op.robot.path)
    assert route.intersection(world.zone("staff_room").polygon).length > 1.0
    report = run.run(120.0)
    claims = {c.kind: c for g in report.groups for c in g.claims}
    assert claims["robot_look"].status == "holds", claims["robot_look"].evidence
    assert claims["reach"].status == "holds", claims["reach"].evidence
