"""How long the grounding report says a run needs (generation/route_time.py): the planned paths, not the
straight line, so a route round corridors is given the time it takes, measured on a real run."""

from __future__ import annotations

import math

import pytest
from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.generation.route_time import PATH_MARGIN
from grove_tui.scenario.report import HOLDS

# Exam room 1 to ward B: 16 m as the crow flies, some 70 m down the corridors.
DETOUR = "Two patients walk from exam room 1 to ward b."


@pytest.fixture(scope="module")
def detour(hospital, tmp_path_factory):
    return plan_by_hand(hospital, "normal", DETOUR,
                        (DraftGroup("patients", 2, "exam_room_1", DraftNode("GoTo", {"target": "ward_b"})),),
                        tmp_path_factory.mktemp("detour") / "bundle")


def _reach(report):
    return next(c for c in report.groups[0].claims if c.kind == "reach")


def test_the_legs_are_the_planned_paths(detour):
    for agent in detour.op.agents:
        path = (agent.start, *agent.goals)
        walked = sum(math.dist(a, b) for a, b in zip(path, path[1:]))
        (leg,) = detour.routes[agent.id]
        assert leg.planned and leg.metres == pytest.approx(walked, abs=0.01)
        assert walked > 2.5 * math.dist(agent.start, agent.goals[-1])  # the route detours


def test_the_time_a_reach_needs_follows_the_planned_path(detour):
    slowest = max(leg.metres / agent.max_vel for agent in detour.op.agents for leg in detour.routes[agent.id])
    needs = _reach(detour.report).needs_seconds
    assert needs is not None and PATH_MARGIN * slowest <= needs <= PATH_MARGIN * slowest + 15.0


def test_a_run_as_long_as_the_report_says_shows_the_reach(detour):
    # straight legs times 1.5 gave 42 s: half the walk, and the run ended with nobody there
    needs = _reach(detour.report).needs_seconds
    assert needs is not None
    reach = _reach(detour.run(needs))
    assert reach.status == HOLDS, reach.evidence
    arrived = float(reach.evidence.rsplit("t = ", 1)[1].split(" s")[0])
    assert needs < 1.6 * arrived  # a margin, not a guess twice too long
