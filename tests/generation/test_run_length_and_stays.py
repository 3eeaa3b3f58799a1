"""A run long enough for what the sentence asks, and groups that stay where the sentence puts them.

Before: a run that left its length to the scenario did not exist (`grove simulate` ran 30 s, `generate
--simulate` needed a number), so a patrol the robot needs minutes for was "not checked"; "patrols between
the entrance and the reading tables" was planned and checked at wherever the round happened to end (a ✓
at the armchairs for a patrol to the entrance); and "two friends talk in the cafe", "students study at the
reading tables and keep away from the robot" had no claim that they stay there."""

from __future__ import annotations

import pytest
from helpers.planned_run import plan_by_hand

from grove_tui.analysis.outcomes import check_bundle
from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.generation.run_length import RUN_CAP, run_length, scenario_seconds
from grove_tui.scenario.report import HOLDS, UNCHECKED, Claim, GroundingReport, GroupGrounding
from grove_tui.services.session import GroveSession
from grove_tui.world import load_world

LIBRARY = "eval/understanding/worlds/library.yaml"
STUDY = DraftNode("Sequence", {}, (DraftNode("GoTo", {"target": "reading_tables"}),
                                   DraftNode("Wait", {"duration": 600.0})))


@pytest.fixture(scope="module")
def library():
    return load_world(LIBRARY)


@pytest.fixture(scope="module")
def patrol(library, tmp_path_factory):
    sentence = "Three students study at the reading tables while the robot patrols between the entrance and the " \
               "reading tables."
    return plan_by_hand(library, "normal", sentence, (DraftGroup("students", 3, "reading_room", STUDY),),
                        tmp_path_factory.mktemp("patrol") / "bundle")


def test_the_patrol_is_planned_and_checked_at_the_place_it_names(patrol, library):
    claim = next(c for c in patrol.report.robot.claims if c.kind == "robot_patrol")
    assert claim.zone == "entrance_foyer" and claim.point is None
    goal = patrol.op.robot.goal
    assert library.zone_at(goal[0], goal[1]).name == "entrance_foyer"


def test_the_scenario_carries_a_length_that_covers_its_claims(patrol):
    length = patrol.report.length
    needs = max(c.needs_seconds or 0.0 for g in patrol.report.groups for c in g.claims)
    needs = max(needs, *(c.needs_seconds or 0.0 for c in patrol.report.robot.claims))
    assert length is not None and needs <= length.needed and length.needed < length.seconds <= RUN_CAP
    # generation.json carries it, and a run left to the scenario runs that long
    assert GroveSession().scenario_run_seconds(patrol.bundle) == length.seconds
    summary = GroveSession().simulate(patrol.bundle)
    assert summary.sim_seconds == pytest.approx(length.seconds, abs=0.1)
    checked = check_bundle(patrol.bundle, write=False)[0]
    robot = {c.kind: c for c in checked.robot.claims}
    assert robot["robot_patrol"].status == HOLDS, robot["robot_patrol"].evidence
    stay = next(c for c in checked.groups[0].claims if c.kind == "stay")
    assert stay.status == HOLDS, stay.evidence
    assert any(line.startswith("run length:") for line in checked.lines())


def test_a_length_the_user_sets_is_kept_and_what_needs_more_is_not_checked(patrol):
    GroveSession().simulate(patrol.bundle, 20.0)
    checked = check_bundle(patrol.bundle, write=False)[0]
    assert checked.run is not None and checked.run.seconds == pytest.approx(20.0, abs=0.1)
    patrol_claim = next(c for c in checked.robot.claims if c.kind == "robot_patrol")
    assert patrol_claim.status == UNCHECKED and "needs about" in patrol_claim.evidence
    assert "the scenario's length is" in checked.summary()


def test_a_length_past_the_cap_is_capped_and_said():
    long_wait = Claim("stay", "the lobby for 3600 s", "wait", zone="lobby", seconds=3600.0, needs_seconds=3620.0)
    report = GroundingReport("x", (GroupGrounding("a", "a", (long_wait,)),))
    length = run_length(report)
    assert length.seconds == RUN_CAP and length.capped and "capped" in length.line()
    assert scenario_seconds({"grounding": report.to_dict()}) == RUN_CAP


def test_two_friends_talking_in_the_cafe_stay_there(library, tmp_path):
    talk = DraftNode("Sequence", {}, (DraftNode("GoTo", {"target": "cafe"}), DraftNode("Converse", {})))
    run = plan_by_hand(library, "normal", "Two friends talk in the cafe.", (DraftGroup("friends", 2, "cafe", talk),),
                       tmp_path / "b")
    stay = next(c for c in run.report.groups[0].claims if c.kind == "stay")
    assert stay.zone == "cafe"
    checked = {c.kind: c for c in run.run(run.report.length.seconds).groups[0].claims}
    assert checked["stay"].status == HOLDS, checked["stay"].evidence
    assert checked["converse"].status == HOLDS, checked["converse"].evidence


def test_students_who_keep_away_from_the_robot_stay_in_their_room(library, tmp_path):
    sentence = "Four students study at the reading tables and keep away from the robot while the robot crosses " \
               "the reading room."
    run = plan_by_hand(library, "normal", sentence, (DraftGroup("students", 4, "reading_room", STUDY),),
                       tmp_path / "b")
    stay = next(c for c in run.report.groups[0].claims if c.kind == "stay")
    # keeping away steps off the tables (crowd/keep_in_place.py): the stay is judged on the room
    assert stay.zone == "reading_room" and stay.point is None
    checked = {c.kind: c for c in run.run(run.report.length.seconds).groups[0].claims}
    assert checked["stay"].status == HOLDS, checked["stay"].evidence
    assert checked["robot_avoid"].status == HOLDS, checked["robot_avoid"].evidence


def test_the_apps_run_does_not_end_before_the_scenarios_length():
    from types import SimpleNamespace

    from grove_tui.tui.screens.sim_controller import SimulationController

    class Done:  # every person is done with their tree from the start; the robot's round goes on
        dt, time = 0.05, 5.0

        def run_state(self):
            return SimpleNamespace(over=True, agents=3, out=0)

    sim = Done()
    controller = SimulationController(sim, run_until=150.0)  # type: ignore[arg-type]
    controller._check_end()
    assert controller.ended is None
    sim.time = 150.0
    controller._check_end()
    assert controller.ended is not None and controller.ended.t == 150.0


def test_a_robot_still_driving_to_its_goal_when_the_run_ends_is_not_checked(patrol, library):
    # "the robot leads them to the nearest exit": slowed by the 40 people it leads, it was 3 m from the door
    # when the run ended, driving on; the estimate (without the crowd) had passed, and it said "never reached"
    from dataclasses import replace

    GroveSession().simulate(patrol.bundle, 25.0)
    robot = patrol.report.robot
    short = replace(patrol.report, robot=replace(robot, claims=tuple(
        replace(c, needs_seconds=12.0) for c in robot.claims if c.kind == "robot_patrol")))
    claim = patrol.check(short, library).robot.claims[0]
    assert claim.status == UNCHECKED and "run it longer" in claim.evidence, claim.evidence

