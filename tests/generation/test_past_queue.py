"""A robot that passes people goes past them, beside them, and on. "Eight patients queue at the pharmacy while
the robot drives past them to the cafeteria" was planned as "through the queue": the robot drove into the line
(0.6 m from a patient) and the report said both "passes through the patients" ✓ and "passes beside the people
at pharmacy" ✗. Now the robot's words say how it passes (language/passing_manner.py), its way runs beside the
line and on (generation/past_queue.py), and one claim says how near it came and whether beside or into them.
A robot that passes a long queue it reacts to goes on past them, not parking beside them
(generation/goes_on_past.py). A look "as the robot passes" is counted from each one in place
(analysis/passing_window.py), and "as it passes the gateline" (a zone) while the robot is in it. Planned from
hand-written drafts (no model) and real simulations."""

from __future__ import annotations

import math

import numpy as np
import pytest
from helpers.planned_run import plan_by_hand

from grove_tui.analysis.outcomes import PASS_BY
from grove_tui.analysis.passing_window import PassingWindow
from grove_tui.generation.beside_queue import BESIDE
from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.language.passing_manner import passes_through
from grove_tui.language.reading import read_prompt
from grove_tui.scenario.events import SimEvent
from grove_tui.world import load_world

HOSPITAL = "worlds/hospital.yaml"
PAST = "Eight patients queue at the pharmacy while the robot drives past them to the cafeteria"
QUEUE = (DraftGroup("patient", 8, "pharmacy", DraftNode("Queue", {"service_point": "pharmacy_counter"})),)


@pytest.mark.parametrize("sentence, through", [
    (PAST, False),
    ("Eight patients queue at the pharmacy while the robot drives through the queue to the cafeteria", True),
    ("Eight patients queue at the pharmacy while the robot threads its way among them to the cafeteria", True),
])
def test_the_robot_words_say_through_or_past(sentence, through):
    reading = read_prompt(sentence, load_world(HOSPITAL))
    assert reading.robot is not None and reading.robot.passes
    assert passes_through(reading.robot) is through


@pytest.fixture(scope="module")
def past(tmp_path_factory):
    world = load_world(HOSPITAL)
    run = plan_by_hand(world, "normal", PAST, QUEUE, tmp_path_factory.mktemp("past") / "b")
    return world, run


def test_one_claim_of_the_passing_beside_them(past):
    world, run = past
    robot = run.report.robot
    passes = [c for c in robot.claims if c.kind == "robot_passes"]
    assert len(passes) == 1 and not any(c.kind == "robot_beside" for c in robot.claims), robot.claims
    claim = passes[0]
    assert claim.low == BESIDE and claim.distance == PASS_BY and "past the patients" in claim.asked, claim
    # its way keeps off the line: never within BESIDE + 0.5 of the queue's places
    slots = [tuple(a) for a in ((48.4, 8.0),)]
    path = np.asarray(run.op.robot.path, dtype=float)
    assert min(math.dist(tuple(p), slots[0]) for p in path) > BESIDE + 0.5, run.op.robot.path


def test_the_robot_passes_beside_the_queue_in_the_run(past):
    world, run = past
    report = run.run(160.0)
    claim = next(c for c in report.robot.claims if c.kind == "robot_passes")
    assert claim.status == "holds", claim.evidence
    assert "passed beside them: nearest" in claim.evidence, claim.evidence


def test_a_robot_passing_a_long_queue_goes_on_past_it(tmp_path):
    tree = DraftNode("Sequence", {}, (DraftNode("GoTo", {"target": "pharmacy"}),
                                      DraftNode("Queue", {"service_point": "pharmacy"})))
    world = load_world("hospital")
    run = plan_by_hand(world, "normal", "Fourteen patients queue at the pharmacy and look at the robot as it "
                       "passes.", (DraftGroup("patients", 14, "main_corridor", tree),), tmp_path / "b")
    head = world.find("pharmacy_counter").interaction_point
    goal = run.op.robot.goal
    # it parked 4.2 m from the counter, beside the head of the queue; now it goes on
    assert math.dist(goal, head) >= PASS_BY, (goal, run.op.robot.path)


def test_a_look_as_it_passes_counts_from_each_one_in_place():
    window = PassingWindow()
    t = np.arange(1, 101) * 0.1  # 10 s
    sight = np.ones((100, 2), dtype=bool)
    looking = np.zeros((100, 2), dtype=bool)
    looking[:20, 0] = True  # member 0 looked while still walking to the queue (before t = 5 s)
    looking[60:80, 1] = True  # member 1 looked once in place
    speed = np.full((100, 2), 1.0)
    window.add(t, sight, looking, speed)
    events = {7: [SimEvent(5.0, 7, "queue_join", "pharmacy_counter")], 8: [SimEvent(5.0, 8, "queue_join", "x")]}
    since = window.in_place([7, 8], events)
    assert since is not None and list(since) == [5.0, 5.0]
    in_sight, facing, longest, passed, looked = window.counted(since, 0.1)
    assert facing[0] == 0 and longest[1] == 20, (facing, longest)
    assert looked == [pytest.approx(6.1), pytest.approx(8.0)]
    said = window.said([7, 8], since)
    assert "7: in place t = 5.0 s, did not look" in said and "8: in place t = 5.0 s, looked t = 6.1 s" in said


def test_a_look_as_it_passes_a_zone_is_checked_while_it_is_in_it(tmp_path):
    run = plan_by_hand(load_world("station"), "normal", "A guard looks at the robot as it passes the gateline on its "
                       "way to the platforms", (DraftGroup("guard", 1, "concourse", DraftNode("LookAtRobot", {})),),
                       tmp_path / "b")
    look = next(c for g in run.report.groups for c in g.claims if c.kind == "robot_look")
    assert look.moment == "pass" and look.place == "gateline" and "passes gateline" in look.asked, look
    report = run.run(40.0)
    look = next(c for g in report.groups for c in g.claims if c.kind == "robot_look")
    assert "the robot passed gateline from" in look.evidence, look.evidence
