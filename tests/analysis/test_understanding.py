"""The understanding suite: its generator, its scorer, and the reader measured against the issue's bars."""

from __future__ import annotations

from helpers.paths import REPO
import importlib.util
import sys
from pathlib import Path
from collections import Counter

import pytest
from click.testing import CliRunner

from grove_tui.analysis.understanding import (
    THRESHOLD,
    THRESHOLD_FIELDS,
    UnderstandingCase,
    UnderstandingError,
    below_threshold,
    expected_total,
    idle_tree,
    load_cases,
    run_reading,
    sample_cases,
    score_reading,
    summarize_reading,
)
from grove_tui.bt.format.manifest import NODES
from grove_tui.bt.format.xml import read_tree
from grove_tui.world import list_worlds, load_world

ROOT = REPO
CASES = ROOT / "eval" / "understanding" / "cases.yaml"
ACTIONS = frozenset(name for name, spec in NODES.items() if spec.category == "action")


def _build_module():
    spec = importlib.util.spec_from_file_location("understanding_build", ROOT / "eval" / "understanding" / "build.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up by name
    spec.loader.exec_module(module)
    return module


# --- the suite -------------------------------------------------------------------------------------


def test_cases_file_is_what_the_generator_builds():
    build = _build_module()
    assert build.render(build.build_cases()) == CASES.read_text(encoding="utf-8"), \
        "cases.yaml is stale: python eval/understanding/build.py"


@pytest.mark.slow
def test_suite_covers_every_world_and_class_the_issue_names():
    cases = load_cases(CASES)
    assert len(cases) >= 300
    # Every shipped world is read by one of the suites: the templates cover the four they were written
    # for, the hand-written sets the others (worlds/station.yaml, worlds/museum.yaml), which no template uses.
    hand_written = {c.world for path in sorted(CASES.parent.glob("*.yaml")) if path != CASES
                    for c in load_cases(path)}
    assert {c.world for c in cases} >= {"hospital", "office", "residential", "airport"}
    assert {c.world for c in cases} | hand_written >= set(list_worlds())
    classes = Counter(c.cls for c in cases)
    for needed in ("compound_2", "compound_3", "vague_count", "structured", "whole_zone", "purpose", "exclusive",
                   "negation", "evacuate", "wait_duration", "pace", "others", "subset", "more"):
        assert classes[needed] >= 4, needed
    groups = [g for c in cases for g in c.groups]
    assert {g.get("robot_reaction") for g in groups} >= {"Surprised", "Curious", "Scared", "Threatening", None}
    assert {g["count"]["kind"] for g in groups if isinstance(g["count"].get("kind"), str)} >= {
        "exact", "approximate", "vague", "implied", "structured", "whole_zone", "exclusive"}
    assert {len(c.groups) for c in cases} >= {1, 2, 3}
    assert len({c.prompt for c in cases}) == len(cases)


@pytest.mark.slow
def test_expected_places_are_the_worlds_own_names_and_are_said_in_the_prompt():
    build = _build_module()
    for case in load_cases(CASES):
        world = load_world(case.world)
        forms = build.world_places(world)
        for group in case.groups:
            for role in ("start", "destination", "location"):
                if group.get(role):
                    place = forms[group[role]]  # KeyError: not a place the suite may name
                    said = case.prompt.lower()
                    assert any(form in said for form in place.forms), (case.id, role, place.name)


def test_generator_is_deterministic_and_seeded_per_world_and_class():
    build = _build_module()
    first, second = build.build_cases(), build.build_cases()
    assert first == second
    assert build.third_person("hurry") == "hurries" and build.third_person("approach") == "approaches"
    assert build.conjugate("slowly make their way to", True) == "slowly makes their way to"


def test_load_cases_reports_bad_files(tmp_path):
    with pytest.raises(UnderstandingError, match="no such cases file"):
        load_cases(tmp_path / "missing.yaml")
    bad = tmp_path / "bad.yaml"
    bad.write_text("cases:\n  - id: x\n    world: office\n", encoding="utf-8")
    with pytest.raises(UnderstandingError, match=r"cases\[0\]") as info:
        load_cases(bad)
    assert info.value.exit_code == 2 and "build.py" in info.value.hint


def test_an_intent_the_reader_cannot_give_is_refused_when_the_cases_load(tmp_path):
    typo = tmp_path / "typo.yaml"
    typo.write_text("cases:\n  - id: talkers\n    world: office\n    prompt: Three clerks have a natter.\n"
                    "    expect:\n      groups:\n      - {count: {value: 3}, intent: talk}\n", encoding="utf-8")
    with pytest.raises(UnderstandingError, match=r"talkers.*intent 'talk' is not one of walk, queue"):
        load_cases(typo)
    robot = tmp_path / "robot.yaml"
    robot.write_text("cases:\n  - id: r\n    world: office\n    prompt: The robot dances.\n"
                     "    expect:\n      groups: []\n      robot: {task: dance}\n", encoding="utf-8")
    with pytest.raises(UnderstandingError, match="robot task 'dance'"):
        load_cases(robot)


def test_every_shipped_cases_file_loads():
    files = sorted((Path(__file__).resolve().parents[2] / "eval" / "understanding").glob("*.yaml"))
    assert len(files) >= 20
    for path in files:
        assert load_cases(path)


# --- the scorer ------------------------------------------------------------------------------------


def _case(groups, unknown=()):
    return UnderstandingCase("t-1", "office", "normal", "walk", "prompt", tuple(groups), tuple(unknown))


def _group(**fields):
    base = {"who": "engineers", "label": "engineer", "count": {"kind": "exact", "value": 4, "low": 4, "high": 4},
            "intent": "walk", "robot_interaction": None, "robot_reaction": None, "start": None,
            "destination": None, "location": None, "via": [], "purpose": None, "wait_seconds": None,
            "together": False, "pace": "normal", "relation": None}
    base.update(fields)
    return base


def test_a_reading_that_says_what_is_expected_passes_every_field():
    expected = {"count": {"kind": "exact", "value": 4}, "intent": "walk", "start": "kitchen",
                "destination": "boardroom", "robot_reaction": None, "pace": "normal", "together": False}
    score = score_reading(_case([expected]), {"groups": [_group(start="kitchen", destination="boardroom")],
                                              "unknown_places": []}, frozenset(NODES))
    assert score.misses == []
    assert all(all(v) for v in score.checks.values())
    assert score.checks["places"] == [True] and score.checks["false_refusals"] == [True]


@pytest.mark.parametrize("expected, read, named", [
    ("café", "cafe", True), ("cafe", "café", True), ("Crèche", "the creche", True), ("café", "canteen", False)])
def test_a_refusal_names_the_place_whatever_its_accents(expected, read, named):
    score = score_reading(_case([], unknown=(expected,)), {"groups": [], "unknown_places": [read]}, frozenset(NODES))
    assert score.checks == {"unknown_place_refusals": [named]}, score.misses


def test_a_via_written_as_one_name_is_one_place_not_its_letters():
    expected = {"count": {"kind": "exact", "value": 4}, "intent": "walk", "via": "kitchen", "destination": "boardroom"}
    right = score_reading(_case([expected]), {"groups": [_group(via=["kitchen"], destination="boardroom")],
                                              "unknown_places": []}, frozenset(NODES))
    assert right.checks["via"] == [True] and right.checks["places"] == [True]
    wrong = score_reading(_case([expected]), {"groups": [_group(via=["hallway"], destination="boardroom")],
                                              "unknown_places": []}, frozenset(NODES))
    assert wrong.checks["via"] == [False]


def test_each_wrong_field_fails_on_its_own():
    expected = {"count": {"kind": "vague", "range": [2, 5]}, "intent": "wait", "location": "kitchen",
                "wait_seconds": 300.0, "robot_reaction": None, "pace": "normal", "purpose": "coffee"}
    reading = _group(count={"kind": "vague", "value": 9, "low": 2, "high": 9}, intent="wait", location="boardroom",
                     wait_seconds=300.0, purpose="for coffee", label="Wait")
    score = score_reading(_case([expected]), {"groups": [reading], "unknown_places": []}, frozenset(NODES))
    failed = {name for name, values in score.checks.items() if not all(values)}
    assert failed == {"count", "location", "places", "label"}


def test_a_missing_group_fails_its_fields_and_the_found_one_is_aligned():
    first = {"count": {"kind": "exact", "value": 4}, "intent": "queue", "location": "coffee_machine"}
    second = {"count": {"kind": "vague", "range": [2, 5]}, "intent": "wander", "location": "kitchen"}
    reading = {"groups": [_group(count={"kind": "vague", "value": 3, "low": 2, "high": 5}, intent="wander",
                                 location="kitchen")], "unknown_places": []}
    score = score_reading(_case([first, second]), reading)
    assert score.checks["groups"] == [False]
    assert score.checks["intent"] == [False, True]  # the reading's group is the second expected one


def test_refusals_are_scored_apart_from_false_refusals():
    refused = score_reading(_case([{"intent": "walk"}], unknown=["swimming pool"]),
                            {"groups": [], "unknown_places": ["the swimming pool"]})
    assert refused.checks == {"unknown_place_refusals": [True]}
    false = score_reading(_case([{"intent": "walk"}]), {"groups": [_group()], "unknown_places": ["except"]})
    assert false.checks["false_refusals"] == [False]
    table = summarize_reading([refused, false])
    assert table["false_refusals"] == (1, 1)
    assert any("false unknown-place refusals" in line for line in below_threshold(table))


def test_scenario_helpers():
    assert expected_total([{"count": {"kind": "exact", "value": 5}},
                           {"count": {"kind": "exact", "value": 1}, "relation": "subset_of:0"},
                           {"count": {"kind": "vague", "range": [2, 5]}}]) == (7, 10)
    idle = '<root BTCPP_format="4"><BehaviorTree ID="a"><Sequence><IsRobotVisible/></Sequence></BehaviorTree></root>'
    moving = ('<root BTCPP_format="4"><BehaviorTree ID="a"><Sequence><IsRobotVisible/>'
              '<Action ID="GoTo" target="kitchen"/></Sequence></BehaviorTree></root>')
    assert "IsRobotVisible" in NODES and NODES["IsRobotVisible"].category == "condition"
    assert idle_tree(read_tree(idle), ACTIONS) and not idle_tree(read_tree(moving), ACTIONS)
    cases = load_cases(CASES)
    sample = sample_cases(cases, 20)
    assert len(sample) == 20 and len({c.world for c in sample}) == 4 and not any(c.unknown_places for c in sample)
    assert len({c.cls for c in sample}) == 20  # one case per class until the classes run out
    assert {"robot_look", "evacuate", "queue", "compound_2"} <= {c.cls for c in sample}
    assert sample_cases(cases, 20) == sample and len(sample_cases(cases, 40)) == 40


def test_scenario_checks_on_a_hand_built_bundle(tmp_path):
    from helpers.handmade import build_hospital_bundle

    from grove_tui.analysis.understanding import score_scenario
    from grove_tui.scenario.bundle import load_trees
    from grove_tui.scenario.model import Scenario

    bundle = build_hospital_bundle(tmp_path / "bundle")
    scenario = Scenario.load(bundle / "scenario.yaml")
    trees = load_trees(bundle, scenario)
    world = load_world("hospital")
    # Five people from the lobby: one surprised by the robot, two queueing at the pharmacy, two talking.
    right = _case([
        {"count": {"kind": "exact", "value": 1}, "intent": "robot", "robot_reaction": "Surprised",
         "start": "entrance_lobby"},
        {"count": {"kind": "exact", "value": 2}, "intent": "queue", "location": "pharmacy_counter"},
        {"count": {"kind": "vague", "range": [2, 3]}, "intent": "converse", "location": "cafeteria_table_1"}])
    score = score_scenario(right, world, scenario, trees, ACTIONS)
    assert score.misses == [] and score.idle_agents == 0
    assert score.checks == {"agent_count": True, "start_zones": True, "destination_zones": None,
                            "location_zones": True, "behavior_types": True, "no_idle_agents": True}
    wrong = _case([{"count": {"kind": "exact", "value": 9}, "destination": "intensive_care",
                    "robot_reaction": "Scared"}])
    score = score_scenario(wrong, world, scenario, trees, ACTIONS)
    assert {name for name, ok in score.checks.items() if ok is False} == {
        "agent_count", "destination_zones", "behavior_types"}
    idle = dict(trees)
    idle[scenario.agents[0].tree] = read_tree('<root BTCPP_format="4"><BehaviorTree ID="a"><Sequence>'
                                              '<IsRobotVisible/></Sequence></BehaviorTree></root>')
    assert score_scenario(right, world, scenario, idle, ACTIONS).idle_agents == 1


def test_cli_writes_the_tables(tmp_path):
    pytest.importorskip("grove_tui.language.reading")
    from grove_tui.cli import main

    small = tmp_path / "cases.yaml"
    text = CASES.read_text(encoding="utf-8")
    head, _, rest = text.partition("cases:\n")
    entries = rest.split("\n- id: ")
    small.write_text(head + "cases:\n" + "\n- id: ".join(entries[:6]) + "\n", encoding="utf-8")
    result = CliRunner().invoke(main, ["understanding", str(small), "--out", str(tmp_path / "out")],
                                catch_exceptions=False)
    assert result.exit_code == 0, result.output
    report = (tmp_path / "out" / "RESULTS.md").read_text(encoding="utf-8")
    assert "| count |" in report and "grove understanding" in report
    assert (tmp_path / "out" / "results.csv").read_text(encoding="utf-8").count("\n") == 7


# --- the reader against the issue's bars -------------------------------------------------------------


# No model, about 20 s for the whole suite: it runs with the other unit tests in CI.
@pytest.mark.slow
def test_reader_meets_the_issue_thresholds_on_the_whole_suite():
    pytest.importorskip("grove_tui.language.reading")
    table = summarize_reading(run_reading(load_cases(CASES)))
    failures = below_threshold(table)
    assert not failures, (f"each of {', '.join(THRESHOLD_FIELDS)} must be >= {THRESHOLD:.0%} with no false "
                          f"refusal: " + "; ".join(failures))
