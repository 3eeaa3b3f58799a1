"""How long the grounding report says a run needs (generation/route_time.py): the planned paths, not the
straight line, so a route round corridors is given the time it takes, measured on a real run."""

from __future__ import annotations

import math

import pytest

from grove_tui.analysis.outcomes import check_bundle
from grove_tui.generation.draft import Draft, DraftGroup, DraftNode
from grove_tui.generation.pipeline import GenerationResult
from grove_tui.generation.planning import plan_operational
from grove_tui.generation.postprocess import postprocess
from grove_tui.generation.presets import load_preset
from grove_tui.generation.reconcile import grounding_report
from grove_tui.generation.rois import select_rois
from grove_tui.generation.route_time import PATH_MARGIN, planned_routes, planning_mode
from grove_tui.language.reading import read_prompt
from grove_tui.navigation.grid import build_grid
from grove_tui.scenario.bundle import write_bundle
from grove_tui.scenario.model import Scenario
from grove_tui.scenario.report import HOLDS
from grove_tui.services.session import GroveSession

# Exam room 1 to ward B: 16 m as the crow flies, some 70 m down the corridors.
DETOUR = "Two patients walk from exam room 1 to ward b."


@pytest.fixture(scope="module")
def detour(hospital, tmp_path_factory):
    """The sentence planned by hand-written draft (no model), its report, and the bundle."""
    preset = load_preset("normal")
    grid = build_grid(hospital)
    reading = read_prompt(DETOUR, hospital)
    draft = Draft((DraftGroup("patients", 2, "exam_room_1", DraftNode("GoTo", {"target": "ward_b"})),))
    post = postprocess(hospital, grid, preset, draft, select_rois(hospital, preset, reading), 0, reading,
                       ("Sequence", "GoTo"))
    op = plan_operational(hospital, grid, preset, post, 0, reading=reading)
    routes = planned_routes(op.agents, op.trees, planning_mode(preset.velocity, preset.planner.enabled))
    report = grounding_report(reading, post.groups, post.agents, hospital, robot=op.robot,
                              walking_speed=preset.max_vel, routes=routes)
    scenario = Scenario(world="hospital", preset=preset.name, prompt=DETOUR, seed=0, models={"bt": "hand"},
                        agents=tuple(op.agents), robot=op.robot)
    result = GenerationResult(scenario, op.trees, op.fields, grid,
                              {"stages": {}, "notes": post.notes, "grounding": report.to_dict()})
    return op, routes, report, write_bundle(result, tmp_path_factory.mktemp("detour") / "bundle")


def _reach(report):
    return next(c for c in report.groups[0].claims if c.kind == "reach")


def test_the_legs_are_the_planned_paths(detour):
    op, routes, _, _ = detour
    for agent in op.agents:
        path = (agent.start, *agent.goals)
        walked = sum(math.dist(a, b) for a, b in zip(path, path[1:]))
        (leg,) = routes[agent.id]
        assert leg.planned and leg.metres == pytest.approx(walked, abs=0.01)
        assert walked > 2.5 * math.dist(agent.start, agent.goals[-1])  # the route detours


def test_the_time_a_reach_needs_follows_the_planned_path(detour):
    op, routes, report, _ = detour
    slowest = max(leg.metres / agent.max_vel for agent in op.agents for leg in routes[agent.id])
    needs = _reach(report).needs_seconds
    assert needs is not None and PATH_MARGIN * slowest <= needs <= PATH_MARGIN * slowest + 15.0


def test_a_run_as_long_as_the_report_says_shows_the_reach(detour):
    # straight legs times 1.5 gave 35 s: half the walk, and the run ended with nobody there
    _, _, report, bundle = detour
    needs = _reach(report).needs_seconds
    assert needs is not None
    GroveSession().simulate(bundle, needs)
    checked, _ = check_bundle(bundle, write=False)
    reach = _reach(checked)
    assert reach.status == HOLDS, reach.evidence
    arrived = float(reach.evidence.rsplit("t = ", 1)[1].split(" s")[0])
    assert needs < 1.6 * arrived  # a margin, not a guess twice too long
