"""The grounding suite's scoring (analysis/grounding_eval.py): hand outcomes against a bundle's report.

The full suite runs in `bench/grounding_suite.py` (figures in eval/grounding/RESULTS.md); here the
suite file is checked, the scoring is tested on hand-drafted bundles (no model), and a sample of the
suite runs end to end with the embedded model (slow).
"""

from __future__ import annotations

import pytest
from helpers.hand_bundle import group, hand_bundle, node
from helpers.paths import REPO

from grove_tui.analysis.grounding_eval import (
    ExpectedGroup,
    GroundingCase,
    SuiteError,
    figures,
    load_suite,
    score_bundle,
)

SUITE = REPO / "eval" / "grounding" / "suite.yaml"


def test_the_public_suite_is_wide():
    cases = load_suite(SUITE)
    assert len(cases) >= 80
    assert {c.world for c in cases} >= {"hospital", "office", "residential", "airport", "station", "museum", "mall"}
    assert {c.preset for c in cases} == {"emergency", "queuing", "normal"}
    reactions = {v for c in cases for g in c.groups for k, v in g.expect if k == "robot"}
    assert reactions == {"follow", "approach", "block", "avoid", "look", "stare"}
    assert {k for c in cases for k, _ in c.robot} >= {"reach", "stay", "patrol", "follow", "passes"}
    assert sum(len(c.groups) > 1 for c in cases) >= 15


def test_a_broken_suite_names_the_case(tmp_path):
    bad = tmp_path / "suite.yaml"
    bad.write_text("cases:\n  - id: x\n    world: hospital\n    preset: normal\n    prompt: p\n"
                   "    groups: [{who: visitors, expect: {swim: pool}}]\n", encoding="utf-8")
    with pytest.raises(SuiteError, match=r"cases\[0\] \(x\).*unknown outcome.*swim"):
        load_suite(bad)


CASE = GroundingCase("home-back-door", "residential", "emergency",
                     "five people in the kitchen get out through the back door", 0, 40.0,
                     (ExpectedGroup("people", (("start", "kitchen"), ("evacuate", ["back_door"])), 5),))


@pytest.mark.slow
def test_a_scenario_that_does_what_was_asked_scores_its_outcome_and_its_tick(tmp_path, session):
    _, bundle = hand_bundle(tmp_path / "b", CASE.world, CASE.preset, CASE.prompt,
                            [group("people", 5, "kitchen", node("FollowVelocityField"))])
    session.simulate(bundle, CASE.seconds)
    score = score_bundle(CASE, bundle)
    (people,) = score.groups
    assert people.outcome and people.report == "holds" and not people.false_tick, people.evidence


def test_a_tick_the_hand_outcome_contradicts_is_a_false_tick(tmp_path, session):
    # The same run, judged by a reader who expected them through the front door: the report's ✓ (they
    # went out through the back door, as the sentence says) is false for that reader.
    _, bundle = hand_bundle(tmp_path / "b", CASE.world, CASE.preset, CASE.prompt,
                            [group("people", 5, "kitchen", node("FollowVelocityField"))])
    session.simulate(bundle, CASE.seconds)
    other = GroundingCase(CASE.id, CASE.world, CASE.preset, CASE.prompt, 0, CASE.seconds,
                          (ExpectedGroup("people", (("evacuate", ["front_door"]),), 5),))
    score = score_bundle(other, bundle)
    assert score.groups[0].false_tick and not score.groups[0].outcome
    totals = figures([score])
    assert (totals.false_ticks, totals.report_ticks, totals.held_share) == (1, 1, 0.0)


@pytest.mark.slow
def test_a_sample_of_the_suite_end_to_end_with_the_embedded_model(tmp_path, session):
    wanted = ("hosp-queue-pharmacy-nurse-walks", "mall-queue-info-robot-crosses")
    cases = [c for c in load_suite(SUITE) if c.id in wanted]
    scores = []
    for case in cases:
        from grove_tui.services.session import ScenarioRequest

        made = session.generate(ScenarioRequest(case.world, case.preset, case.prompt, case.seed), tmp_path / case.id)
        session.simulate(made.bundle_dir, case.seconds)
        scores.append(score_bundle(case, made.bundle_dir))
    totals = figures(scores)
    assert totals.false_ticks == 0
    assert totals.held_share == 1.0, [g.evidence for s in scores for g in s.groups if not g.outcome]
