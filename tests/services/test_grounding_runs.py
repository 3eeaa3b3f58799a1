"""Issue 28 end to end (no model: hand drafts as a weak model writes them, the real reader, stages,
simulation and outcome checks): what the issue's new user met, now.

The checked report is written by `GroveSession.simulate` (the path of `grove simulate`, `generate
--simulate`, batch and the app's exports) into grounding.json, beside metrics.json.
"""

from __future__ import annotations

import json
import math

import pytest
from helpers.hand_bundle import group, hand_bundle, hand_result, node

from grove_tui.scenario.report import GroundingReport


def checked(bundle) -> GroundingReport:
    return GroundingReport.from_dict(json.loads((bundle / "grounding.json").read_text(encoding="utf-8")))


def claims(report: GroundingReport, who: str) -> dict[str, object]:
    (found,) = [g for g in report.groups if who in g.who]
    return {c.kind: c for c in found.claims}


@pytest.mark.slow
def test_a_walker_the_model_sent_to_queue_walks_and_the_run_shows_it(tmp_path, session):
    # "✓ behavior walk -> GoTo, Queue": the nurse first queued at the pharmacy counter, then walked.
    queue = node("Sequence", node("GoTo", target="pharmacy_counter"), node("Queue", service_point="pharmacy_counter"))
    nurse = node("Sequence", queue, node("GoTo", target="cafeteria"))
    result, bundle = hand_bundle(tmp_path / "b", "hospital", "queuing",
                                 "ten patients queue at the pharmacy while a nurse walks to the cafeteria",
                                 [group("patients", 10, "main_waiting_room", queue), group("nurse", 1, "ward_a", nurse)])
    planned = GroundingReport.from_dict(result.report["grounding"])
    assert planned.status == "planned" and "✓" not in "\n".join(planned.lines())
    nurse_ids = {m for g in planned.groups if "nurse" in g.who for m in g.members}
    session.simulate(bundle, 90.0)
    report = checked(bundle)
    assert claims(report, "nurse")["reach"].status == "holds"
    assert claims(report, "patients")["queue"].status == "holds"
    events = [json.loads(line) for line in (bundle / "events.jsonl").read_text().splitlines()]
    assert not [e for e in events if e["agent_id"] in nurse_ids and e["kind"].startswith("queue")]
    # a run too short to tell says so, with how long it needs, never ✓ nor ✗
    session.simulate(bundle, 3.0)
    short = claims(checked(bundle), "patients")["queue"]
    assert short.status == "unchecked" and "needs about" in short.evidence


def test_reactions_to_the_robot_happen_and_blocking_slows_it(tmp_path, session):
    # The children's trees waited for IsRobotVisible(10) and never came closer than 23 m; nobody blocked.
    gated = node("Sequence", node("IsRobotVisible", distance=10.0), node("FollowAgent"))
    _, bundle = hand_bundle(tmp_path / "b", "hospital", "normal", "two children follow the robot while a nurse blocks its way",
                            [group("children", 2, "ward_a", gated), group("nurse", 1, "ward_a", node("Wait", duration=10.0))])
    session.simulate(bundle, 60.0)
    report = checked(bundle)
    follow, block = claims(report, "children")["robot_follow"], claims(report, "nurse")["robot_block"]
    assert follow.status == "holds", follow.evidence
    assert block.status == "holds" and "slowed it" in block.evidence, block.evidence
    assert any(json.loads(line)["kind"] == "robot_stopped" for line in (bundle / "events.jsonl").read_text().splitlines())
    # Blocking is standing in the way, not in the robot's body: the blocker's forces keep the robot as an
    # obstacle (it had ignored it and stood inside it, 19 robot-on-person contacts in a 40 s mall run).
    robot = json.loads((bundle / "metrics.json").read_text())["robot"]
    assert robot["robot_on_person_collision"] == 0, robot


@pytest.mark.slow
def test_the_robot_is_a_subject_and_groups_never_take_its_places(tmp_path, session):
    prompt = "twelve travellers queue at the ticket office while a robot crosses the ticket hall to the platforms"
    queue = node("Sequence", node("GoTo", target="ticket_office"), node("Queue", service_point="ticket_office"),
                 node("GoTo", target="platform_1"))
    result, bundle = hand_bundle(tmp_path / "b", "station", "queuing", prompt,
                                 [group("travellers", 12, "platform_1", queue)])
    planned = GroundingReport.from_dict(result.report["grounding"])
    travellers = planned.groups[0]
    assert not [c for c in travellers.claims if c.zone in ("platform_1", "platform_2") or c.place == "platform_1"]
    assert result.report["groups"][0]["spawn"] not in ("platform_1", "platform_2")
    robot = planned.robot
    assert robot is not None and robot.task == "cross" and {c.kind for c in robot.claims} >= {"robot_via", "robot_reach"}
    world = result.scenario.robot
    from grove_tui.world import load_world

    assert load_world("station").zone_at(*world.start).name == "ticket_hall"
    session.simulate(bundle, 120.0)
    report = checked(bundle)
    assert report.robot.status == "holds", report.lines()
    assert claims(report, "travellers")["queue"].status == "holds"


def test_the_robot_starts_2_m_clear_of_everyone_and_outside_the_room_being_evacuated():
    # Issue 31 item 9: the robot started in the boardroom being evacuated, 2.1 m from an agent.
    result = hand_result("office", "emergency", "everyone in the boardroom evacuates",
                         [group("people", 10, "boardroom", node("FollowVelocityField"))])
    robot = result.scenario.robot
    from grove_tui.world import load_world

    office = load_world("office")
    assert office.zone_at(*robot.start).name != "boardroom"
    assert min(math.dist(robot.start, a.start) for a in result.scenario.agents) >= 2.0
