"""Refining a scenario by follow-ups (generation/refine.py): the diff before anything runs, untouched
groups byte for byte, kept members, the model asked for the new groups alone, the history, the robot.

The model is a scripted one here, to count its calls and read what it is asked (as the re-planning
tests do); tests/generation/test_refine_model.py runs the embedded model."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from grove_tui.errors import AmbiguousEditError, EditError
from grove_tui.generation.pipeline import GenerationPipeline
from grove_tui.generation.presets import load_preset
from grove_tui.generation.refine import apply_refinement, plan_refinement, step_seed
from grove_tui.generation.scene import draft_from_document, scene_of
from grove_tui.language.followup import read_followup
from grove_tui.scenario.bundle import load_bundle, load_report, write_bundle
from grove_tui.scenario.history import History
from grove_tui.scenario.report import GroundingReport
from helpers.refining import PROMPT, NoRetrieval, ScriptedLLM, build_base_bundle


@pytest.fixture(scope="module")
def base(hospital, tmp_path_factory):
    """The scenario, written and read back: refinement works from bundles."""
    return build_base_bundle(tmp_path_factory.mktemp("base") / "bundle", hospital)


def opened(bundle: Path):
    from grove_tui.generation.pipeline import GenerationResult

    scenario, trees, fields, grid = load_bundle(bundle)
    return GenerationResult(scenario, trees, fields, grid, load_report(bundle))


def refine(hospital, bundle: Path, sentence: str, out: Path, llm: ScriptedLLM | None = None, preset="queuing"):
    llm = llm or ScriptedLLM()
    pipeline = GenerationPipeline(hospital, load_preset(preset), None, llm, NoRetrieval())
    scene = scene_of(opened(bundle), hospital)
    edit = read_followup(sentence, hospital, [g.reading for g in scene.groups])
    refinement = plan_refinement(scene, edit)
    return refinement, write_bundle(apply_refinement(pipeline, scene, refinement), out)


def files_of(bundle: Path, members: list[int]) -> dict[str, bytes]:
    return {f"trees/agent_{m}.xml": (bundle / f"trees/agent_{m}.xml").read_bytes() for m in members}


def agents_of(bundle: Path, members: list[int]) -> list[Any]:
    scenario = load_bundle(bundle)[0]
    return [a for a in scenario.agents if a.id in members]


def records(bundle: Path) -> list[dict[str, Any]]:
    return json.loads((bundle / "generation.json").read_text(encoding="utf-8"))["groups"]


def test_a_count_edit_keeps_the_other_groups_byte_for_byte_and_calls_no_model(hospital, base, tmp_path):
    llm = ScriptedLLM()
    refinement, out = refine(hospital, base, "make the queue twice as long", tmp_path / "b", llm)
    assert [line[0] for line in refinement.diff.lines()] == ["~", "="]
    assert not refinement.calls_model and llm.asked == []
    before, after = records(base), records(out)
    assert (after[0]["count"], before[0]["count"]) == (20, 10)
    assert after[1:] == before[1:]  # nurses and cleaner: their records as they were
    for group in before[1:]:
        assert files_of(out, group["members"]) == files_of(base, group["members"])
        assert agents_of(out, group["members"]) == agents_of(base, group["members"])
    # the queue's first ten keep their ids, starts and trees; the ten more come after every id there was
    assert files_of(out, list(range(1, 11))) == files_of(base, list(range(1, 11)))
    assert after[0]["members"][:10] == list(range(1, 11))
    assert min(after[0]["members"][10:]) > max(m for g in before for m in g["members"])
    starts = [a.start for a in load_bundle(out)[0].agents]
    assert len(set(starts)) == len(starts)


def test_an_addition_asks_the_model_for_the_new_group_alone(hospital, base, tmp_path):
    llm = ScriptedLLM("2 guards from main_entrance: GoTo(main_entrance)")
    refinement, out = refine(hospital, base, "add two guards standing at the main entrance", tmp_path / "b", llm)
    assert refinement.calls_model and len(llm.asked) == 1
    user = llm.asked[0][-1]["content"]
    lines = user.splitlines()
    groups_line = " ".join(lines[lines.index("Groups:") + 1:])  # the lean draft's numbered groups
    assert "guard x2" in groups_line and "patient" not in groups_line and "nurse" not in groups_line
    before, after = records(base), records(out)
    assert after[:3] == before and after[3]["label"] == "guard" and after[3]["count"] == 2
    assert after[3]["asked_by"] == 1
    for group in before:
        assert files_of(out, group["members"]) == files_of(base, group["members"])
    fields_before = sorted(p.name for p in (base / "fields").glob("*")) if (base / "fields").exists() else []
    assert fields_before == (sorted(p.name for p in (out / "fields").glob("*")) if (out / "fields").exists() else [])


def test_history_and_grounding_cover_every_sentence(hospital, base, tmp_path):
    _, first = refine(hospital, base, "the nurses walk slowly", tmp_path / "one")
    _, second = refine(hospital, first, "remove the cleaner", tmp_path / "two")
    report = load_report(second)
    history = History.from_report(report)
    assert history.sentences == [PROMPT, "the nurses walk slowly", "remove the cleaner"]
    assert [line[0] for line in history.steps[1].diff.lines()] == ["-", "="]
    grounding = GroundingReport.from_dict(report["grounding"])
    assert list(grounding.sentences) == history.sentences
    nurse = next(g for g in grounding.groups if g.label == "nurse")
    assert (nurse.asked_by, nurse.changed_by) == (0, (1,))
    assert "changed by 2" in "\n".join(grounding.lines())
    # checked on a run (here one with no frames yet), the report still says who asked for what
    from grove_tui.analysis.outcomes import OutcomeChecker

    checked = OutcomeChecker(grounding, load_bundle(second)[0], hospital).result([], partial=True)
    assert checked.checked and checked.sentences == grounding.sentences
    assert [(g.asked_by, g.changed_by) for g in checked.groups] == [(g.asked_by, g.changed_by) for g in grounding.groups]
    assert GroundingReport.from_dict(checked.to_dict()).sentences == grounding.sentences
    assert [g["label"] for g in report["groups"]] == ["patient", "nurse"]
    slow = [a.max_vel for a in load_bundle(second)[0].agents if a.label == "nurse"]
    assert slow and all(v < load_preset("queuing").max_vel for v in slow)


def test_the_same_follow_up_gives_the_same_bundle(hospital, base, tmp_path):
    _, one = refine(hospital, base, "make the queue twice as long", tmp_path / "one")
    _, two = refine(hospital, base, "make the queue twice as long", tmp_path / "two")
    for name in ("scenario.yaml", *[f"trees/{p.name}" for p in (one / "trees").glob("*.xml")]):
        assert (one / name).read_bytes() == (two / name).read_bytes()
    assert step_seed(2, 1) != step_seed(2, 2)


def test_the_robot(hospital, base, tmp_path):
    _, waits = refine(hospital, base, "the robot waits at reception", tmp_path / "waits")
    robot = load_bundle(waits)[0].robot
    assert robot is not None and robot.start == robot.goal and hospital.zone_at(*robot.start).name == "entrance_lobby"
    _, gone = refine(hospital, waits, "no robot", tmp_path / "gone")
    assert load_bundle(gone)[0].robot is None
    assert records(gone) == records(waits)
    _, back = refine(hospital, gone, "add a robot", tmp_path / "back")
    assert load_bundle(back)[0].robot is not None
    _, patrol = refine(hospital, back, "the robot patrols the main corridor", tmp_path / "patrol")
    robot = load_bundle(patrol)[0].robot
    assert {hospital.zone_at(*robot.start).name, hospital.zone_at(*robot.goal).name} == {"main_corridor"}
    assert len(robot.path) >= 2 and robot.start != robot.goal
    _, crosses = refine(hospital, patrol, "now the robot crosses the lobby to the lifts", tmp_path / "crosses")
    robot = load_bundle(crosses)[0].robot
    assert hospital.zone_at(*robot.goal).name == "elevator_hall"
    assert records(crosses) == records(base)  # the robot's edits left every group as it was
    _, follows = refine(hospital, crosses, "the robot follows the nurses", tmp_path / "follows")
    robot = load_bundle(follows)[0].robot
    nurses = next(g["members"] for g in records(base) if g["label"] == "nurse")
    assert robot.task == "follow" and list(robot.follows) == nurses
    claim = GroundingReport.from_dict(load_report(follows)["grounding"]).robot.claims[0]
    assert claim.kind == "robot_follow_person" and list(claim.partners) == nurses


def test_a_name_two_groups_share_is_asked_about(hospital, base, tmp_path):
    llm = ScriptedLLM("1 nurse from reception_desk: GoTo(reception_desk)")
    _, two_nurses = refine(hospital, base, "add a nurse waiting at reception", tmp_path / "b", llm)
    scene = scene_of(opened(two_nurses), hospital)
    edit = read_followup("the nurse walks slowly", hospital, [g.reading for g in scene.groups])
    with pytest.raises(AmbiguousEditError) as caught:
        plan_refinement(scene, edit)
    (phrase, options), = caught.value.choices
    assert phrase == "the nurse" and [index for index, _ in options] == [1, 3]
    assert "nurse ×2" in caught.value.message and "nurse ×1" in caught.value.message
    settled = plan_refinement(scene, edit.choose(0, 3))
    assert [c.label for c in settled.diff.groups] == ["nurse"] and settled.diff.groups[0].after.count == 1


def test_a_follow_up_that_changes_nothing_is_refused(hospital, base):
    scene = scene_of(opened(base), hospital)
    for sentence in ("the lights are off", "remove the janitor"):
        with pytest.raises(EditError):
            plan_refinement(scene, read_followup(sentence, hospital, [g.reading for g in scene.groups]))
    everyone = read_followup("remove everyone", hospital, [g.reading for g in scene.groups])
    with pytest.raises(EditError, match="nobody"):
        plan_refinement(scene, everyone)


def test_a_tree_read_back_from_its_xml(base):
    from grove_tui.bt.format.xml import read_tree

    tree = draft_from_document(read_tree((base / "trees/agent_1.xml").read_text(), "agent_1"))
    assert [n.node for n in tree.walk()] == ["Sequence", "GoTo", "Queue"]
    assert tree.children[1].ports["service_point"] in ("pharmacy", "pharmacy_counter")  # its counter


def test_counts_edited_on_a_saved_bundle_are_a_refinement(base, tmp_path):
    from grove_tui.services.session import GroveSession

    with GroveSession() as session:  # no model loads: a count edit calls none
        opened_bundle = session.open_bundle(base)
        edited = session.replan(opened_bundle, {0: 12}, tmp_path / "edited")
        assert session.loaded_models() == []
    report = load_report(edited.bundle_dir)
    assert report["history"][0]["sentence"] == "counts: patient 12"
    assert [g["count"] for g in report["groups"]] == [12, 2, 1]
    assert report["groups"][1:] == records(base)[1:]


@pytest.mark.slow
def test_evacuees_added_under_the_emergency_preset_need_no_model(hospital, tmp_path):
    """Under a preset that evacuates along fields an evacuating group's tree is the field to its exit,
    whatever a model writes, so adding one asks no model; the groups already there stay as they were."""
    draft = "10 people from cafeteria: FollowVelocityField(main_entrance)\n3 guards from entrance_lobby: Wait"
    base = build_base_bundle(tmp_path / "base", hospital, preset="emergency",
                             prompt="ten people evacuate from the cafeteria while three guards wait in the lobby",
                             draft=draft)
    llm = ScriptedLLM()  # asked for anything, it fails the test
    refinement, out = refine(hospital, base, "also six visitors evacuate from ward a", tmp_path / "b", llm,
                             preset="emergency")
    assert not refinement.calls_model and llm.asked == []
    before, after = records(base), records(out)
    assert after[:2] == before and after[2]["label"] == "visitor" and after[2]["count"] == 6
    visitors = [a for a in load_bundle(out)[0].agents if a.label == "visitor"]
    assert len(visitors) == 6 and all(hospital.zone_at(*a.start).name == "ward_a" for a in visitors)
    xml = (out / visitors[0].tree).read_text(encoding="utf-8")
    assert "FollowVelocityField" in xml
    for group in before:
        assert files_of(out, group["members"]) == files_of(base, group["members"])
