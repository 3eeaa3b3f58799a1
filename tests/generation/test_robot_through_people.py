"""A robot sent through people who stay somewhere sets off from the next room and is checked to pass them
(generation/robot_passing.py, reconcile's robot_passes): "the robot threads its way through the crowd of
visitors in the main waiting room to reach the lifts". Planned from hand-written drafts (no model) and run
in the real simulation: the report's ✓ are measured."""

from __future__ import annotations

import pytest
from helpers.planned_run import plan_by_hand

from grove_tui.analysis.grounding_eval import ExpectedGroup, GroundingCase, score_bundle
from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.scenario.report import HOLDS
from grove_tui.world import load_world

# (world, sentence, the zone the people stay in)
CASES = {
    "hospital-crowd": ("hospital", "The robot threads its way through the crowd of visitors in the main waiting room "
                       "to reach the lifts.", "main_waiting_room"),
    "station-crowd": ("station", "The robot picks its way through a crowd of commuters on the concourse to reach "
                      "platform 2.", "concourse"),
}


@pytest.fixture(scope="module", params=sorted(CASES))
def passing_run(request, tmp_path_factory):
    world_name, sentence, zone = CASES[request.param]
    world = load_world(world_name)
    stay = DraftNode("Sequence", {}, (DraftNode("Wait", {"duration": 120.0}),))
    run = plan_by_hand(world, "normal", sentence, (DraftGroup("people", 12, zone, stay),),
                       tmp_path_factory.mktemp(request.param) / "bundle")
    seconds = max(c.needs_seconds or 0.0 for c in run.report.robot.claims) + 10.0
    return world, zone, run, run.run(seconds)


def test_the_robot_sets_off_outside_the_room_it_is_sent_through(passing_run):
    world, zone, run, _ = passing_run
    assert world.zone_at(*run.op.robot.start) != zone


def test_the_robot_is_claimed_and_measured_to_pass_them(passing_run):
    _, zone, _, checked = passing_run
    passes = [c for c in checked.robot.claims if c.kind == "robot_passes"]
    assert passes and passes[0].zone == zone
    assert passes[0].status == HOLDS, passes[0].evidence


def _queue_run(world_name: str, sentence: str, service: str, people: int, out):
    world = load_world(world_name)
    queue = DraftNode("Sequence", {}, (DraftNode("Queue", {"service_point": service}),))
    return world, plan_by_hand(world, "queuing", sentence, (DraftGroup("people", people, service, queue),), out)


def test_a_robot_sent_through_a_queue_goes_through_it(tmp_path):
    """The queue is an obstacle the robot's planner keeps clear of, except the one its clause goes through:
    there it crosses the line (and stops and creeps while people make way), so the report's ✓ is measured."""
    _, run = _queue_run("hospital", "Ten patients queue at the pharmacy while the robot drives through the queue "
                        "to the cafeteria.", "pharmacy_counter", 10, tmp_path / "bundle")
    checked = run.run(max(c.needs_seconds or 0.0 for c in run.report.robot.claims) + 10.0)
    passes = next(c for c in checked.robot.claims if c.kind == "robot_passes")
    assert passes.status == HOLDS, passes.evidence
    reach = next(c for c in checked.robot.claims if c.kind == "robot_reach")
    assert reach.status == HOLDS, reach.evidence
    # the room is passed through to the people, in and out by whichever door: no crossing of it is asked
    via = next(c for c in checked.robot.claims if c.kind == "robot_via")
    assert via.status == HOLDS, via.evidence
    # the grounding suite's hand outcome (eval/grounding/suite.yaml's `passes`) agrees on the same run
    case = GroundingCase("through-queue", "hospital", "queuing", run.report.prompt, 0, 0.0,
                         (ExpectedGroup("patients", (("queue", "pharmacy_counter"),), 10),),
                         (("passes", "patients"),))
    (hand,) = [g for g in score_bundle(case, run.bundle).groups if g.who == "the robot"]
    assert hand.outcome, hand.evidence


@pytest.mark.parametrize("world_name, sentence, service, not_from", [
    # the check-in hall's only inner door leads to the checkpoint: it sets off in the hall, away from it
    ("airport", "Nine passengers queue at check-in counter A and the robot cuts through the queue to the security "
     "checkpoint.", "check_in_counter_a", ("security_checkpoint",)),
    ("hospital", "Ten patients queue at the pharmacy while the robot drives through the queue to the cafeteria.",
     "pharmacy_counter", ("cafeteria", "pharmacy")),
])
def test_a_robot_sent_through_people_does_not_set_off_where_it_is_going(world_name, sentence, service, not_from,
                                                                          tmp_path):
    """It sets off from a room next to the people's on the far side from its goal, or among them when there is
    none, never in the goal's own room (a reach ✓ at t = 0.1 s would claim a way it never drove)."""
    world, run = _queue_run(world_name, sentence, service, 8, tmp_path / "bundle")
    start_zone = world.zone_at(*run.op.robot.start)
    assert start_zone is not None
    assert start_zone.name not in not_from


@pytest.mark.parametrize("world, sentence, passes", [
    ("hospital", "Ten patients queue at the pharmacy while the robot drives through the queue to the cafeteria.",
     ("Ten patients",)),
    ("station", "Twelve travellers queue at the ticket office while a robot crosses the ticket hall to the platforms.",
     ()),
    ("mall", "Six shoppers wait by the fountain as the robot rolls through the atrium to the food court.", ()),
])
def test_only_people_the_robots_clause_goes_through_are_to_be_passed(world, sentence, passes):
    """Crossing the hall where people queue is no asking to pass them: only the people its own clause goes
    through, past or around are (`RobotReading.passes`)."""
    from grove_tui.language.reading import read_prompt

    robot = read_prompt(sentence, load_world(world)).robot
    assert robot is not None and robot.passes == passes
