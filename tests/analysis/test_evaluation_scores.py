"""Evaluation scores on hand-made scenarios with known answers."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from grove_tui.analysis.evaluation import (
    EvalCase,
    EvalError,
    Expectation,
    behavior_match,
    count_accuracy,
    decoupled_agents,
    grounding,
    load_suite,
    stop_and_go_share,
    validity,
)
from grove_tui.bt.format.xml import read_tree, write_tree
from grove_tui.navigation.grid import build_grid
from grove_tui.scenario.bundle import load_trees
from grove_tui.analysis.metrics import Trajectories
from grove_tui.scenario.model import Scenario
from grove_tui.world import load_world


def _trees(bundle, scenario):
    trees = load_trees(bundle, scenario)
    return {a.id: trees[a.tree] for a in scenario.agents}


def test_grounding_counts_targets_in_named_zones_and_entities(bundle, hospital):
    scenario = Scenario.load(bundle / "scenario.yaml")
    # agents 1-3 head for the pharmacy counter, 4-5 for a cafeteria table
    assert grounding(hospital, scenario.agents, Expectation(targets=("pharmacy",)))["target_grounding"] == 0.6
    assert grounding(hospital, scenario.agents, Expectation(targets=("pharmacy_counter",)))["target_grounding"] == 0.6
    both = Expectation(targets=("pharmacy", "cafeteria"), spawns=("entrance_lobby",))
    scores = grounding(hospital, scenario.agents, both)
    assert scores["target_grounding"] == 1.0
    assert scores["spawn_grounding"] == 1.0
    assert grounding(hospital, scenario.agents, Expectation(spawns=("ward_a",)))["spawn_grounding"] == 0.0


def test_count_accuracy():
    agents = [None] * 8  # only the length matters
    assert count_accuracy(agents, Expectation(count=10)) == pytest.approx(0.8)
    assert count_accuracy(agents, Expectation(count=8)) == 1.0
    assert count_accuracy(agents, Expectation(count=2)) == 0.0
    assert count_accuracy(agents, Expectation()) is None


def test_behavior_match_and_validity_catch_invented_nodes_and_places(bundle, hospital):
    scenario = Scenario.load(bundle / "scenario.yaml")
    trees = _trees(bundle, scenario)
    assert behavior_match(trees, Expectation(behaviors=("Queue", "Converse"))) == 1.0
    assert behavior_match(trees, Expectation(behaviors=("Queue", "FollowVelocityField"))) == 0.5
    clean = validity(hospital, trees)
    assert clean == {"valid_trees": 1.0, "hallucinated_node_types": 0.0, "hallucinated_places": 0.0}
    broken = dict(trees)
    broken[1] = read_tree(write_tree(trees[1]).replace("<Wait ", "<Teleport ")
                          .replace('target="pharmacy_counter"', 'target="helipad"'))
    dirty = validity(hospital, broken)
    assert dirty["valid_trees"] == pytest.approx(4 / 5)
    assert dirty["hallucinated_node_types"] == 1.0
    assert dirty["hallucinated_places"] == 1.0


def test_stop_and_go_needs_a_real_stop_then_walking_on():
    t = np.arange(0, 4.0, 0.1)
    rows = []
    for f, tt in enumerate(t):
        walk_stop_walk = 1.0 if tt < 1.0 or tt >= 2.5 else 0.0  # stops 1.5 s
        always = 1.0
        short = 0.0 if 1.0 <= tt < 1.3 else 1.0  # stops 0.3 s: not a stop
        for agent_id, v in ((1, walk_stop_walk), (2, always), (3, short)):
            rows.append([f, tt, agent_id, tt, agent_id, v, 0.0, 0.0, -1])
    traj = Trajectories.from_rows(np.asarray(rows))
    assert stop_and_go_share(traj) == pytest.approx(1 / 3)


def test_decoupled_baseline_ignores_the_prompt_but_keeps_the_population(bundle, hospital):
    scenario = Scenario.load(bundle / "scenario.yaml")
    grid = build_grid(hospital, 0.1)
    decoupled = decoupled_agents(hospital, scenario.agents, seed=1, grid=grid)
    assert [a.id for a in decoupled] == [a.id for a in scenario.agents]
    assert all(grid.is_free(*a.start) and grid.is_free(*a.goals[-1]) for a in decoupled)
    assert decoupled_agents(hospital, scenario.agents, seed=1, grid=grid) == decoupled  # deterministic


def test_suite_errors_name_the_case(tmp_path):
    path = tmp_path / "suite.yaml"
    path.write_text("cases:\n  - id: a\n    world: hospital\n    preset: normal\n")
    with pytest.raises(EvalError, match=r"cases\[0\]: missing key 'prompt'"):
        load_suite(path)
    case = EvalCase("a", "hospital", "normal", "x", 0, Expectation())
    assert dataclasses.replace(case, seed=2).seed == 2


def test_shipped_suite_covers_every_world_and_preset_with_real_names():
    from grove_tui.paths import PROJECT_ROOT

    cases = load_suite(PROJECT_ROOT / "eval" / "suite.yaml")
    assert len(cases) >= 30
    assert {(c.world, c.preset) for c in cases} >= {
        (w, p) for w in ("hospital", "office", "residential") for p in ("emergency", "queuing", "normal")}
    for case in cases:
        world = load_world(case.world)
        for name in case.expect.targets + case.expect.spawns:
            world.find(name)  # raises on a name the world does not have
    assert {"two-groups", "vague", "synonym"} <= {t for c in cases for t in c.tags}


def test_roaming_agents_are_grounded_by_the_zone_they_roam(hospital):
    from grove_tui.scenario.model import AgentSpec

    agent = AgentSpec(id=1, group=-1, start=(30.0, 5.0), goals=(), zone="entrance_lobby", tree="trees/agent_1.xml")
    tree = ('<root BTCPP_format="4" main_tree_to_execute="a"><BehaviorTree ID="a">'
            '<Wander zone="cafeteria" duration="30"/></BehaviorTree></root>')
    tree = read_tree(tree)
    assert grounding(hospital, [agent], Expectation(targets=("cafeteria",)), {1: tree})["target_grounding"] == 1.0
    assert grounding(hospital, [agent], Expectation(targets=("food_counter",)), {1: tree})["target_grounding"] == 1.0
    assert grounding(hospital, [agent], Expectation(targets=("pharmacy",)), {1: tree})["target_grounding"] == 0.0


def test_a_failed_generation_scores_zero_not_missing():
    from grove_tui.analysis.evaluation import CaseResult, summarize

    case = EvalCase("c", "hospital", "normal", "p", 0, Expectation(targets=("pharmacy",), count=3))
    ok = CaseResult(case, "grove", {"target_grounding": 1.0, "count_accuracy": 1.0})
    failed = CaseResult(case, "vanilla", error="context too small")
    summary = summarize([ok, failed])
    assert summary[("normal", "vanilla")]["target_grounding"] == 0.0
    assert summary[("normal", "vanilla")]["failed"] == 1.0
    assert "spawn_grounding" not in summary[("normal", "vanilla")]  # the case has no spawn expectation


def test_the_no_planner_baseline_walks_straight_into_walls(bundle, hospital):
    """GROVE's planned patient (agent 2) reaches the pharmacy counter through the door; without waypoints
    and without run-time planning (HuNavSim's straight goals) the wall between lobby and pharmacy stops them."""
    from grove_tui.analysis.evaluation import without_planner
    from grove_tui.analysis.metrics import Trajectories
    from grove_tui.services.session import GroveSession

    def simulate_for_scores(bundle, seconds, runtime_planning=True):
        GroveSession().simulate(bundle, seconds, runtime_planning=runtime_planning)
        return Trajectories.from_csv(bundle / "trajectories.csv")

    scenario = Scenario.load(bundle / "scenario.yaml")
    counter = hospital.find("pharmacy_counter").interaction_point

    def final_distance(traj) -> float:
        k = list(traj.ids).index(2)
        pts = traj.people[:, k]
        x, y = pts[np.isfinite(pts[:, 0])][-1]
        return float(np.hypot(x - counter[0], y - counter[1]))

    grove_traj = simulate_for_scores(bundle, 40.0)
    straight_scenario, straight_trees = without_planner(scenario, load_trees(bundle, scenario))
    straight = GroveSession().write_variant(bundle, bundle.parent / "straight", straight_scenario, straight_trees)
    straight_traj = simulate_for_scores(straight, 40.0, runtime_planning=False)
    assert final_distance(grove_traj) < 2.5
    assert final_distance(straight_traj) > 4.0


def test_the_bundles_own_grounding_report_is_scored_for_grove_only():
    from grove_tui.analysis.evaluation import grounding_report_scores

    report = {"grounding": {"prompt": "p", "ok": False, "unhonoured": ["'except the lobby': no such place"],
                            "groups": [{"who": "ten patients", "ok": True}, {"who": "a family", "ok": False},
                                       {"who": "a guard", "ok": True}, {"who": "others", "ok": True}]}}
    assert grounding_report_scores(report) == {"report_unhonoured": 1.0, "report_groups_ok": 0.75}
    assert grounding_report_scores({"stages": {}}) == {}  # bundles written before the report existed
    assert grounding_report_scores(None) == {}
