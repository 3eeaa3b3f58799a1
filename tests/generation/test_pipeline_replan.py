"""Re-planning with edited head counts: post-processing and planning again, no model call."""

from __future__ import annotations

import copy
import threading
from pathlib import Path
from typing import Any

import pytest

from grove_tui.bt.format.xml import validate_document, write_tree
from grove_tui.scenario.bundle import write_bundle
from grove_tui.generation.pipeline import GenerationPipeline, StageFinished, StageStarted
from grove_tui.navigation.theta_star import ThetaStarPlanner
from grove_tui.generation.planning import goals_from_tree
from grove_tui.generation.presets import GenerationError, PromptError, load_preset
from grove_tui.generation.retrieval import NodeRetriever
from grove_tui.errors import Cancelled
from grove_tui.llm.local import Generation

PROMPT = "Ten patients queue at the pharmacy counter while two nurses walk from the lobby to the cafeteria"
DRAFT = ("10 patients from pharmacy: Sequence(GoTo(pharmacy_counter), Queue(pharmacy_counter))\n"
         "2 nurses from lobby: GoTo(cafeteria)")


class CountingLLM:
    """Answers with a fixed draft and counts its calls: re-planning must never call it."""

    def __init__(self, text: str) -> None:
        self.text = text
        self.path = Path("counting.gguf")
        self.calls = 0

    def generate(self, messages: Any, grammar: str | None = None, **_: Any) -> Generation:
        self.calls += 1
        return Generation(self.text, "stop", 100, 40, 0.01, 0.001)


class NoRetrieval(NodeRetriever):
    """The real node database; ranking is not under test here, the preset's required nodes suffice."""

    def retrieve(self, prompt: str, preset: Any = None, k: int = 8) -> list[Any]:
        return []


@pytest.fixture(scope="module")
def no_retrieval():
    return NoRetrieval()


def make_pipeline(clinic, no_retrieval, llm=None, preset="queuing"):
    return GenerationPipeline(clinic, load_preset(preset), None, llm or CountingLLM(DRAFT), no_retrieval)


@pytest.fixture(scope="module")
def planned(clinic, no_retrieval):
    llm = CountingLLM(DRAFT)
    pipeline = make_pipeline(clinic, no_retrieval, llm)
    result = pipeline.run(PROMPT, seed=3)
    assert llm.calls == 1
    return pipeline, llm, result


def labels_and_counts(result):
    return [(g["label"], g["count"]) for g in result.report["groups"]]


def test_counts_change_the_population_exactly_without_calling_the_model(planned):
    pipeline, llm, result = planned
    assert labels_and_counts(result) == [("patient", 10), ("nurse", 2)]
    events = []
    edited = pipeline.replan(result, {0: 14, 1: 3}, on_event=events.append)
    assert llm.calls == 1, "re-planning called the model"
    assert labels_and_counts(edited) == [("patient", 14), ("nurse", 3)]
    agents = edited.scenario.agents
    assert [a.id for a in agents] == list(range(1, 18))
    assert sum(a.label == "patient" for a in agents) == 14 and sum(a.label == "nurse" for a in agents) == 3
    assert edited.report["groups"][0]["members"] == list(range(1, 15))
    assert edited.report["groups"][1]["members"] == [15, 16, 17]
    # only the two replayed stages ran
    assert [type(e).__name__ + ":" + e.stage for e in events] == [
        "StageStarted:postprocess", "StageFinished:postprocess", "StageStarted:planning", "StageFinished:planning"]
    assert all(isinstance(e, (StageStarted, StageFinished)) for e in events)


def test_the_report_says_what_the_sentence_asked_and_what_the_user_changed(planned):
    # issue 28: after 10 -> 20 the count is not "✓ ten patients x20 / ✓ count 20"
    from grove_tui.scenario.report import GroundingReport

    pipeline, _, result = planned
    edited = pipeline.replan(result, {0: 14})
    report = GroundingReport.from_dict(edited.report["grounding"])
    patients = report.groups[0]
    (count,) = [c for c in patients.claims if c.kind == "count"]
    assert count.asked == "10" and count.plan == "14 people (edited from 10)" and count.status == "planned"
    assert patients.edit == "the sentence asked 10 ('Ten patients'); you changed it to 14"
    assert not report.groups[1].edit
    # a second edit still says what the sentence asked
    again = GroundingReport.from_dict(pipeline.replan(edited, {0: 20}).report["grounding"])
    assert again.groups[0].edit.startswith("the sentence asked 10 ") and again.groups[0].edit.endswith("to 20")
    assert any(line.strip().startswith("! the sentence asked 10") for line in again.lines())


def test_every_tree_validates_and_has_planned_waypoints(planned):
    pipeline, _, result = planned
    edited = pipeline.replan(result, {0: 7})
    assert len(edited.trees) == len(edited.scenario.agents) == 9
    planner = ThetaStarPlanner(edited.grid)
    for agent in edited.scenario.agents:
        document = edited.trees[agent.tree]
        assert validate_document(document) is document
        assert list(document.trees) == [f"agent_{agent.id}"]
        assert agent.goals == tuple(goals_from_tree(document))
        route = [agent.start, *agent.goals]
        assert all(planner.segment_is_free(a[0], a[1], b[0], b[1]) for a, b in zip(route, route[1:])), agent.id
    # lobby -> cafeteria is no straight line: the nurses' GoTo carries injected waypoints
    nurses = [a for a in edited.scenario.agents if a.label == "nurse"]
    assert len(nurses) == 2
    legs = [el for a in nurses for el in edited.trees[a.tree].nodes() if "waypoints" in el.attributes]
    assert legs and all(el.get("waypoints") for el in legs)
    assert edited.scenario.robot is not None and len(edited.scenario.robot.path) >= 2


def test_report_keeps_earlier_stages_and_records_the_edit(planned):
    pipeline, _, result = planned
    edited = pipeline.replan(result, {0: 12})
    old, new = result.report, edited.report
    for stage in ("rois", "retrieval", "synthesis"):
        assert new["stages"][stage] == old["stages"][stage]
    assert set(new["stages"]) == {"rois", "retrieval", "synthesis", "postprocess", "planning"}
    assert new["prompt_tokens"] == old["prompt_tokens"] and new["completion_tokens"] == old["completion_tokens"]
    assert new["draft"] == old["draft"] and new["draft_text"] == old["draft_text"]
    assert new["notes"][0] == "counts edited: patient 10 -> 12"
    assert new["count_edits"] == [{"counts": {"0": 12}, "seed": 3, "note": "counts edited: patient 10 -> 12"}]
    # a second edit builds on the first and keeps the history
    again = pipeline.replan(edited, {1: 4})
    assert labels_and_counts(again) == [("patient", 12), ("nurse", 4)]
    assert again.report["notes"][0] == "counts edited: nurse 2 -> 4"
    assert [e["note"] for e in again.report["count_edits"]] == [
        "counts edited: patient 10 -> 12", "counts edited: nurse 2 -> 4"]


def test_same_result_counts_and_seed_give_the_same_bundle(planned, tmp_path):
    pipeline, _, result = planned
    first = pipeline.replan(result, {0: 11, 1: 3})
    second = make_pipeline(pipeline.world, pipeline.retriever).replan(result, {0: 11, 1: 3})
    assert first.scenario == second.scenario
    assert first.trees == second.trees
    a, b = write_bundle(first, tmp_path / "a"), write_bundle(second, tmp_path / "b")
    assert (Path(a) / "scenario.yaml").read_text() == (Path(b) / "scenario.yaml").read_text()
    for rel, document in first.trees.items():
        assert (Path(b) / rel).read_text() == write_tree(document)
    other = pipeline.replan(result, {0: 11, 1: 3}, seed=4)
    assert other.scenario.seed == 4
    assert [a.start for a in other.scenario.agents] != [a.start for a in first.scenario.agents]
    assert "re-planned with seed 4" in other.report["notes"][1]


def test_same_counts_reproduce_the_original_run(planned):
    pipeline, _, result = planned
    same = pipeline.replan(result, {0: 10, 1: 2})
    assert same.scenario == result.scenario and same.trees == result.trees


@pytest.mark.parametrize("counts, message", [
    ({0: 0}, "group 'patient': 0 people is out of range; preset 'queuing' allows 1 to"),
    ({1: 41}, "group 'nurse': 41 people is out of range"),
    ({2: 3}, "there is no group 2"),
    ({0: "7"}, "is not a whole number"),
    ({}, "no counts to change"),
])
def test_counts_out_of_range_are_refused(planned, counts, message):
    pipeline, _, result = planned
    with pytest.raises(GenerationError, match=message.replace("(", r"\(")):
        pipeline.replan(result, counts)


def test_too_many_people_for_the_zone_are_refused_and_the_result_is_unchanged(clinic, no_retrieval):
    draft = "2 nurses from restroom: GoTo(lobby)"
    pipeline = make_pipeline(clinic, no_retrieval, CountingLLM(draft), preset="normal")
    result = pipeline.run("two nurses walk from the restroom to the lobby", seed=0)
    assert labels_and_counts(result) == [("nurse", 2)]
    before_report = copy.deepcopy(result.report)
    before = (result.scenario, {rel: document.copy() for rel, document in result.trees.items()})
    # The restroom (3 x 2 m) holds a handful of people at a plausible density, not twenty.
    with pytest.raises(PromptError, match="do not fit in") as info:
        pipeline.replan(result, {0: 20})
    assert "restroom" in str(info.value) and "m^2" in str(info.value)
    assert result.report == before_report
    assert (result.scenario, result.trees) == before
    # and the result still re-plans afterwards
    assert labels_and_counts(pipeline.replan(result, {0: 3})) == [("nurse", 3)]


def test_a_result_without_its_draft_cannot_be_replanned(planned):
    pipeline, _, result = planned
    from dataclasses import replace

    with pytest.raises(GenerationError, match="keeps no draft"):
        pipeline.replan(replace(result, inputs=None), {0: 5})


def test_another_preset_pipeline_refuses_the_result(planned, clinic, no_retrieval):
    _, _, result = planned
    with pytest.raises(GenerationError, match="preset 'normal'"):
        make_pipeline(clinic, no_retrieval, preset="normal").replan(result, {0: 5})


def test_without_a_number_the_vague_group_of_the_reading_is_edited(clinic, no_retrieval):
    draft = "3 visitors from cafeteria: GoTo(coffee_counter)"
    pipeline = make_pipeline(clinic, no_retrieval, CountingLLM(draft), preset="normal")
    result = pipeline.run("visitors walk to the coffee counter", seed=0)
    # "visitors" with no number: the reading's vague count (a seeded choice in its documented range)
    vague = result.inputs.reading.groups[0].count
    assert vague.kind == "vague" and labels_and_counts(result) == [("visitor", vague.value)]
    edited = pipeline.replan(result, {0: 6})
    assert labels_and_counts(edited) == [("visitor", 6)]
    assert [a.id for a in edited.scenario.agents] == list(range(1, 7))


def test_emergency_replan_rebuilds_the_group_fields(clinic, no_retrieval):
    draft = "5 visitors from cafeteria: FollowVelocityField(back_exit)"
    pipeline = make_pipeline(clinic, no_retrieval, CountingLLM(draft), preset="emergency")
    result = pipeline.run("five visitors evacuate the cafeteria", seed=0)
    edited = pipeline.replan(result, {0: 9})
    assert len(edited.scenario.agents) == 9 and set(edited.fields) == set(result.fields) == {"group_1"}
    assert all(len(a.goals) >= 1 for a in edited.scenario.agents)


def test_cancel_stops_the_replan(planned):
    pipeline, _, result = planned
    cancel = threading.Event()
    cancel.set()
    with pytest.raises(Cancelled):
        pipeline.replan(result, {0: 5}, cancel=cancel)
