"""One claim per thing asked: "the robot accompanies a patient to radiology" was read as the robot following
the patient and the patient following the robot. Each followed the other, and the report claimed the one
asked behaviour twice (robot_follow for the patient, robot_follow_person for the robot). The robot leads the
people who follow it (generation/mutual_follow.py); the one claim is theirs, and they arrive with it."""

from __future__ import annotations

from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.scenario.report import HOLDS
from grove_tui.world import load_world

SENTENCE = "The robot accompanies a patient to radiology"


def test_the_robot_leads_the_patient_it_accompanies_and_the_following_is_claimed_once(tmp_path):
    hospital = load_world("worlds/hospital.yaml")
    run = plan_by_hand(hospital, "normal", SENTENCE,
                       (DraftGroup("patient", 1, "main_corridor", DraftNode("Wait", {"duration": 5.0})),),
                       tmp_path / "b", as_the_pipeline=True)
    kinds = [c.kind for g in run.report.groups for c in g.claims] + [c.kind for c in run.report.robot.claims]
    assert kinds.count("robot_follow") + kinds.count("robot_follow_person") == 1, kinds
    assert run.op.robot.task == "cross"
    assert hospital.zone_at(*run.op.robot.goal).name == "radiology"
    reach = next(c for c in run.report.groups[0].claims if c.kind == "reach")
    report = run.run(reach.needs_seconds or 120.0)
    checked = {c.kind: c for c in report.groups[0].claims}
    assert checked["robot_follow"].status == HOLDS, checked["robot_follow"].evidence
    assert checked["reach"].status == HOLDS, checked["reach"].evidence
