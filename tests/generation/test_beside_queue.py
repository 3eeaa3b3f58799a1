"""A robot that passes a place where people queue passes beside them. "... while the robot passes the ticket
office" (station): the robot's way was made to pass by the office's own point, the head of the queue, so it
drove within 0.1 m of the service point through the people queueing ("no way around"). Now it passes at the
edge of the queue, and the report checks the run: the nearest it came to someone standing there, with the
figure. Planned from a hand-written draft (no model) and a real simulation."""

from __future__ import annotations

import math
from dataclasses import replace

import pytest
from helpers.planned_run import plan_by_hand

from grove_tui.generation.beside_queue import BESIDE
from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.world import load_world

STATION = "worlds/station.yaml"
SENTENCE = "Eight travellers queue at the ticket office while the robot passes the ticket office"
QUEUE = (DraftGroup("traveller", 8, "ticket_hall", DraftNode("Queue", {"service_point": "ticket_office"})),)


def _robot(report, kind):
    return next(c for c in report.robot.claims if c.kind == kind)


@pytest.fixture(scope="module")
def queue(tmp_path_factory):
    world = load_world(STATION)
    run = plan_by_hand(world, "queuing", SENTENCE, QUEUE, tmp_path_factory.mktemp("beside") / "b")
    return world, run, run.run(60.0)


def test_the_robot_passes_beside_the_queue_not_through_it(queue):
    world, run, report = queue
    office = world.find("ticket_office").interaction_point
    path = run.op.robot.path
    assert min(math.dist(p, office) for p in path) > 1.0, path
    assert not any("no way around" in n for n in run.op.notes), run.op.notes
    beside = _robot(report, "robot_beside")
    assert beside.status == "holds" and "closest to someone standing at ticket_office" in beside.evidence, beside
    assert _robot(report, "robot_via").status == "holds", _robot(report, "robot_via").evidence


def test_a_robot_into_the_queue_is_a_fail_with_the_figure(queue):
    world, run, report = queue
    planned = _robot(run.report, "robot_beside")
    assert planned.distance == BESIDE and len(planned.partners) == 8
    # the same run, asked to keep 3 m from them: it came nearer, and the figure says how near
    strict = replace(planned, distance=3.0)
    robot = replace(run.report.robot, claims=tuple(strict if c.kind == "robot_beside" else c
                                                   for c in run.report.robot.claims))
    checked = _robot(run.check(replace(run.report, robot=robot), world), "robot_beside")
    assert checked.status == "fails" and "3 m or more asked" in checked.evidence, checked.evidence
