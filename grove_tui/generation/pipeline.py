"""The generation pipeline: prompt -> RoIs -> retrieved nodes -> draft -> trees -> planned trees -> Scenario.

    pipeline = GenerationPipeline(world, preset, llm_roi, llm_bt, retriever)
    result = pipeline.run("Ten patients queue at the pharmacy counter", seed=0, on_event=print, cancel=event)
    write_bundle(result, "out/pharmacy")

`replan` reruns only post-processing and planning of an earlier result with edited head counts
(no model call), so the user can change "ten patients" to fourteen without regenerating:

    edited = pipeline.replan(result, {0: 14})

`run` and `replan` are safe to call from a worker thread: progress comes back as plain dataclass events through
`on_event` (called in the caller's thread), and `cancel` (a threading.Event) is checked between
stages, between agents while planning, and during generation (the LLM stops within a second).
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any, NotRequired, TypedDict, cast

from grove_tui.bt.format.document import TreeFiles
from grove_tui.bt.format.xml import validate_document
from grove_tui.navigation.grid import OccupancyGrid, build_grid
from grove_tui.paths import worlds_dir
from grove_tui.navigation.theta_star import PlanCache, ThetaStarPlanner
from grove_tui.generation.draft import Draft, node_to_dict
from grove_tui.jsontypes import JSONObject
from grove_tui.generation.events import AttemptStarted, Event, StageFinished, StageStarted, TokenStreamed
from grove_tui.generation.planning import OperationalPlan, plan_operational
from grove_tui.generation.postprocess import GroupPlan, PostProcessed, check_population, postprocess
from grove_tui.generation.presets import Preset
from grove_tui.generation.requests import MAX_PROMPT_CHARS, RobotRequest
from grove_tui.generation.reconcile import grounding_report, with_followed_person
from grove_tui.generation.route_time import planned_routes, planning_mode
from grove_tui.language.model import Count, GroupReading, PromptReading, effective_counts
from grove_tui.language.reading import read_prompt
from grove_tui.generation.rois import RoISelection, describe_selection, refine_with_model, select_rois
from grove_tui.scenario.history import StageTiming
from grove_tui.scenario.model import Scenario
from grove_tui.generation.synthesis import (SynthesisRequest, SynthesisResult, describe_documents, draft_summary,
                                           prepare_request, synthesize)
from grove_tui.navigation.velocity_field import VelocityField
from grove_tui.errors import EMPTY_PROMPT_HINT, LONG_PROMPT_HINT, BTError, Cancelled, GenerationError, PromptError
from grove_tui.world.model import World

if TYPE_CHECKING:
    from grove_tui.generation.retrieval import NodeRetriever, RetrievedNode
    from grove_tui.llm.local import LocalLLM

STAGES = ("rois", "retrieval", "synthesis", "postprocess", "planning")

__all__ = ["AttemptStarted", "Cancelled", "GenerationError", "GenerationPipeline", "GenerationResult", "PlanInputs",
           "STAGES", "StageFinished", "StageStarted", "TokenStreamed"]


@dataclass(frozen=True)
class PlanInputs:
    """What post-processing and planning consume, kept on the result so counts can be re-planned.

    Group i of the result (report["groups"][i]) is the i-th group of the reading that has people of
    its own (effective_counts): that is how post-processing reconciles the draft with the reading.
    """

    draft: Draft
    selection: RoISelection
    node_names: tuple[str, ...]
    reading: PromptReading  # the sentence as read: its groups are the result's groups
    sentence: PromptReading | None = None  # the reading before the user's count edits (None: no edit yet)

    @property
    def prompt(self) -> str:
        return self.reading.prompt

    def with_counts(self, counts: Mapping[int, int]) -> PlanInputs:
        # Result group i is the i-th reading group that has people of its own (effective_counts).
        order = sorted(effective_counts(self.reading))
        groups = list(self.reading.groups)
        for i, n in counts.items():
            r = order[i]
            inside = sum(g.count.value for g in groups if g.relation == f"subset_of:{r}")
            value = int(n) + inside  # a parent's count includes its subsets ("one of them")
            # an edited count is stated by the user now: sure, whatever the sentence said
            groups[r] = replace(groups[r], count=Count("exact", value, value, value),
                                confidence=tuple(c for c in groups[r].confidence if c.field != "count"))
        return replace(self, reading=replace(self.reading, groups=tuple(groups)), sentence=self.sentence or self.reading)


@dataclass
class GenerationResult:
    scenario: Scenario
    trees: TreeFiles  # relative path ("trees/agent_1.xml") -> the agent's tree, written as XML only into files
    fields: dict[str, VelocityField]
    grid: OccupancyGrid
    report: dict[str, Any] = field(default_factory=dict)  # Any: generation.json, built and read back key by key
    # The draft and prompt analysis the trees came from; None for results rebuilt from a bundle.
    inputs: PlanInputs | None = field(default=None, repr=False, compare=False)
    # Other text files of the bundle, written verbatim beside the trees (an imported HuNavSim scenario's
    # own tree files and world): relative path -> text.
    files: dict[str, str] = field(default_factory=dict)


@dataclass(frozen=True)
class Drafted:
    """What the rois, retrieval and synthesis stages give post-processing (GenerationPipeline.draft)."""

    reading: PromptReading
    selection: RoISelection
    retrieved: tuple[RetrievedNode, ...]
    request: SynthesisRequest
    synthesis: SynthesisResult


def _no_event(event: Event) -> None:
    """The event sink of a caller that listens to nothing."""


class GroupRecord(TypedDict):
    """One entry of generation.json's "groups" (group_records writes it, generation/scene.py reads it back)."""

    label: str
    count: int
    spawn: str
    members: list[int]
    field: str | None  # the velocity field the group follows
    behavior: str  # HuNavSim reaction to the robot
    spawn_zones: NotRequired[dict[str, int]]  # an evacuation spread over several zones: zone -> people
    reading: NotRequired[JSONObject]  # the GroupReading it realises (to_dict), its count the group's people
    # Always written; NotRequired because older bundles' records lack them (their readers default them).
    tree: NotRequired[JSONObject]  # its tree before ids and points (draft.node_to_dict)
    asked_by: NotRequired[int]  # the sentence that asked for it: 0 the first, k the k-th follow-up
    changed_by: NotRequired[list[int]]  # the follow-ups that changed it
    # Read by refine's grounding, never written here: a kept group's extras are in the grounding report only.
    added: NotRequired[list[str]]


def group_records(groups: Sequence[GroupPlan], reading: PromptReading | None, asked_by: int = 0) -> list[GroupRecord]:
    """generation.json's "groups": per post-processed group its label, count, spawn, members and field,
    and what a refinement needs to edit it without the model (generation/refine.py): the reading it
    realises (its count the group's own people), its tree before ids and points (draft form), and the
    sentence that asked for it (0: the first)."""
    records = []
    for g in groups:
        record: GroupRecord = {"label": g.label, "count": g.count, "spawn": g.spawn, "members": list(g.member_ids),
                               "field": g.field_id, "behavior": g.behavior}
        if g.spawn_zones:
            record["spawn_zones"] = dict(g.spawn_zones)
        if g.added:
            record["added"] = list(g.added)  # what the tree does beyond the reading: a follow-up's report lists it again
        index = getattr(g, "reading_index", None)
        if reading is not None and index is not None and 0 <= index < len(reading.groups):
            record["reading"] = own_reading(reading.groups[index], g.count).to_dict()
        record["tree"] = node_to_dict(g.tree)
        record["asked_by"] = asked_by
        records.append(record)
    return records


def own_reading(group: GroupReading, count: int) -> GroupReading:
    """A reading group as the scenario's group realises it: its own people ("one of them" taken out of
    its parent), no relation to the other groups of its sentence."""
    c = group.count
    own = c if c.value == count else Count("exact", count, count, count)
    return replace(group, count=own, relation=None)


class StageClock:
    """Times stages into `stages`, emits their events and checks `cancel` before each one starts."""

    def __init__(self, emit: Callable[[Event], None], cancel: threading.Event | None,
                 stages: dict[str, StageTiming]) -> None:
        self.emit, self.cancel, self.stages = emit, cancel, stages

    def begin(self, stage: str) -> float:
        if self.cancel is not None and self.cancel.is_set():
            raise Cancelled(f"generation cancelled before {stage}")
        self.emit(StageStarted(stage))
        return time.perf_counter()

    def end(self, stage: str, t0: float, detail: str, prompt_tokens: int = 0, completion_tokens: int = 0) -> None:
        seconds = time.perf_counter() - t0
        self.stages[stage] = {"seconds": round(seconds, 4), "prompt_tokens": prompt_tokens,
                              "completion_tokens": completion_tokens}
        self.emit(StageFinished(stage, seconds, prompt_tokens, completion_tokens, detail))


def check_trees(trees: TreeFiles) -> None:
    """GenerationError unless every planned tree is valid against the node manifest (checked as documents:
    nothing is written and read back)."""
    for document in trees.values():
        try:
            validate_document(document)
        except BTError as exc:
            raise GenerationError(f"generated tree failed validation against the node manifest: {exc}") from None


def world_reference(world: World) -> str:
    """How a scenario names its world: the shipped name, or the path of a user's world file."""
    source = world.source
    if source is None:
        return str(world.name)
    source = Path(source)
    try:
        if source.resolve().parent == worlds_dir().resolve():
            return source.stem
    except OSError:
        pass
    return str(source)


def _model_name(llm: object) -> str:
    path = getattr(llm, "path", None)
    return Path(path).name if path is not None else type(llm).__name__


class GenerationPipeline:
    """One world and preset, models loaded once; `run` many prompts."""

    def __init__(self, world: World, preset: Preset, llm_roi: LocalLLM | None, llm_bt: LocalLLM | None,
                 retriever: NodeRetriever | None, resolution: float | None = None, robot: RobotRequest | None = None,
                 plan_cache: PlanCache | None = None, max_tokens: int = 512) -> None:
        self.world = world
        self.preset = preset
        self.llm_roi = llm_roi
        self.llm_bt = llm_bt
        self.retriever = retriever
        self.resolution = float(resolution or preset.planner.resolution)
        self.robot = robot
        self.plan_cache = plan_cache or PlanCache()
        self.max_tokens = max_tokens
        self._grid: OccupancyGrid | None = None
        self._planner: ThetaStarPlanner | None = None

    @property
    def grid(self) -> OccupancyGrid:
        if self._grid is None:
            self._grid = build_grid(self.world, resolution=self.resolution, inflation=self.preset.planner.inflation)
        return self._grid

    def adopt_grid(self, grid: OccupancyGrid | None, resolution: float) -> None:
        """Plan on a scenario's own grid (a re-plan or refinement of it), when this pipeline has built
        none yet and the scenario was planned at this pipeline's resolution: the same world and preset
        give the same grid, so it is not built again."""
        if self._grid is None and grid is not None and resolution == self.resolution:
            self._grid = grid

    @property
    def planner(self) -> ThetaStarPlanner:
        if self._planner is None:
            self._planner = ThetaStarPlanner(self.grid)
        return self._planner

    def run(self, prompt: str, seed: int = 0, on_event: Callable[[Event], None] | None = None,
            cancel: threading.Event | None = None) -> GenerationResult:
        emit = on_event or _no_event
        prompt = " ".join((prompt or "").split())
        if not prompt:
            raise PromptError("the prompt is empty: describe the people and what they do", hint=EMPTY_PROMPT_HINT)
        if len(prompt) > MAX_PROMPT_CHARS:
            raise PromptError(f"the prompt is {len(prompt)} characters long; keep it under {MAX_PROMPT_CHARS}",
                              hint=LONG_PROMPT_HINT)
        preset, world = self.preset, self.world
        stages: dict[str, StageTiming] = {}
        clock = StageClock(emit, cancel, stages)
        started = time.perf_counter()

        drafted = self.draft(prompt, seed, clock, on_event, cancel)
        reading, selection, retrieved = drafted.reading, drafted.selection, drafted.retrieved
        request, synthesis = drafted.request, drafted.synthesis
        inputs = PlanInputs(synthesis.draft, selection, tuple(request.node_names), reading)
        post, plan = self._plan_stages(inputs, seed, clock, cancel)

        models = {"bt": _model_name(self.llm_bt)}
        if self.llm_roi is not None:
            models["roi"] = _model_name(self.llm_roi)
        report = {
            "world": world_reference(world), "preset": preset.name, "prompt": prompt, "seed": int(seed),
            "models": models, "stages": stages,
            "total_seconds": round(time.perf_counter() - started, 4),
            "prompt_tokens": synthesis.prompt_tokens, "completion_tokens": synthesis.completion_tokens,
            "reading": reading.to_dict(),
            "selected_rois": describe_selection(selection), "zones": selection.zones, "named_zones": selection.named_zones,
            "retrieved": [{"name": r.name, "kind": r.kind, "score": r.score, "nodes": list(r.nodes)} for r in retrieved],
            "documents": describe_documents(request.documents), "offered_nodes": request.node_names,
            "draft": draft_summary(synthesis.draft), "draft_text": synthesis.text,
            "attempts": synthesis.attempts, "draft_errors": synthesis.errors,
            "first_token_seconds": None if synthesis.first_token_seconds is None else round(synthesis.first_token_seconds, 4),
            # Prompt tokens the bt model did not evaluate: its live KV or the world+preset prefix restored from disk.
            "cached_tokens": synthesis.cached_tokens, "cache_source": synthesis.cache_source,
        }
        return self._assemble(inputs, seed, models, post, plan, report)

    def draft(self, prompt: str, seed: int, clock: StageClock, on_event: Callable[[Event], None] | None,
              cancel: threading.Event | None, reading: PromptReading | None = None,
              query: str | None = None, documents: int | None = None) -> Drafted:
        """The model's draft for a sentence: the rois (with the reading), retrieval and synthesis stages.

        `run` asks it for the whole sentence, read here; a refinement (generation/refine.py) for the
        groups a follow-up adds or changes, giving their `reading` alone, so the model writes only those,
        with its own retrieval `query` and at most `documents` node documents (fewer groups need fewer,
        and every card is prompt the model must read)."""
        preset, world = self.preset, self.world
        emit = on_event or _no_event
        t0 = clock.begin("rois")
        if reading is None:
            # The sentence is read once, here: everything below takes the reading, and the raw text goes
            # only to the embedder (retrieval) and the models.
            reading = read_prompt(prompt, world, seed=seed)
            if reading.problems:  # no words, a negative or zero count, nobody: refused before anything runs
                raise PromptError(reading.problems[0])
            reading = with_followed_person(reading, world)
        selection = select_rois(world, preset, reading)
        roi_tokens = (0, 0)  # prompt and completion tokens of the roi model
        if self.llm_roi is not None and preset.guided:
            selection, reading, *spent = refine_with_model(world, preset, reading, selection, self.llm_roi, seed,
                                                           cancel)
            roi_tokens = (spent[0], spent[1])
        check_population(world, self.grid, preset, selection, reading)
        clock.end("rois", t0, ", ".join(selection.zones), *roi_tokens)

        retriever, llm_bt = self.retriever, self.llm_bt
        if retriever is None or llm_bt is None:
            raise GenerationError("this pipeline was built to re-plan only: it has no bt model or node index to draft")
        t0 = clock.begin("retrieval")
        k = preset.retrieval_k if documents is None else min(preset.retrieval_k, documents)
        if preset.retrieval_filter is not None and k > 0:
            retrieved = retriever.retrieve(query or prompt, preset.retrieval_filter, k=k)
        else:
            retrieved = []
        request = prepare_request(preset, selection, retrieved, reading, retriever.documents_for, world=world,
                                  cards_for=getattr(retriever, "cards_for", None),
                                  documents_named=getattr(retriever, "documents_named", None))
        clock.end("retrieval", t0, ", ".join(d.name for d in request.documents))

        t0 = clock.begin("synthesis")
        on_token = (lambda text: emit(TokenStreamed("synthesis", text))) if on_event else None
        on_attempt = (lambda attempt, reason: emit(AttemptStarted("synthesis", attempt, reason))) if on_event else None
        synthesis = synthesize(llm_bt, request, preset, seed, on_token=on_token, cancel=cancel,
                               max_tokens=self.max_tokens, on_attempt=on_attempt)
        clock.end("synthesis", t0, f"{len(synthesis.draft.groups)} group(s), {synthesis.attempts} attempt(s)",
                  synthesis.prompt_tokens, synthesis.completion_tokens)
        return Drafted(reading, selection, tuple(retrieved), request, synthesis)

    def replan(self, result: GenerationResult, counts: Mapping[int, int], seed: int | None = None,
               on_event: Callable[[Event], None] | None = None,
               cancel: threading.Event | None = None) -> GenerationResult:
        """`result` with new head counts per group (index into report["groups"] -> count), no model call.

        Only post-processing and planning run again, on the draft `result` kept, with the same checks
        as `run` (GenerationError/PromptError for counts no zone can hold or the preset forbids). The new
        report keeps the earlier stages' timings and tokens and records the edit. `result` is not changed.
        The seed defaults to the result's own, so the same result, counts and seed give the same bundle.
        """
        inputs = result.inputs
        if inputs is None:
            raise GenerationError("this scenario keeps no draft to re-plan (it was loaded from a bundle); "
                                  "regenerate it to change its counts")
        if result.scenario.preset != self.preset.name or result.scenario.world != world_reference(self.world):
            raise GenerationError(f"this pipeline is for world '{world_reference(self.world)}' with preset "
                                  f"'{self.preset.name}', but the scenario is '{result.scenario.world}' with "
                                  f"'{result.scenario.preset}'")
        groups = list(result.report.get("groups", ()))
        edits = self._check_counts(groups, counts)
        seed = int(result.scenario.seed if seed is None else seed)
        self.adopt_grid(result.grid, result.scenario.resolution)  # the same world and preset: the run's grid
        edited = inputs.with_counts(counts)
        check_population(self.world, self.grid, self.preset, edited.selection, edited.reading)

        written = result.report.get("stages", {})
        stages = {k: cast(StageTiming, dict(v)) for k, v in written.items()}  # as the run wrote them
        previous = sum(written.get(s, {}).get("seconds", 0.0) for s in ("postprocess", "planning"))
        clock = StageClock(on_event or (lambda event: None), cancel, stages)
        post, plan = self._plan_stages(edited, seed, clock, cancel)
        for i, count in counts.items():
            if post.groups[i].count != count:  # reconciliation must keep group order; refuse silently wrong counts
                raise GenerationError(f"group '{groups[i]['label']}' came out with {post.groups[i].count} people "
                                      f"instead of {count}; regenerate the scenario")

        report = {k: v for k, v in result.report.items() if k not in ("groups", "exit", "notes", "goals")}
        replanned = sum(stages[s]["seconds"] for s in ("postprocess", "planning"))
        report["stages"] = stages
        report["total_seconds"] = round(float(result.report.get("total_seconds", 0.0)) - previous + replanned, 4)
        report["seed"] = seed
        edit_note = "counts edited: " + ", ".join(f"{label} {old} -> {new}" for label, old, new in edits)
        history = list(result.report.get("count_edits", ()))
        history.append({"counts": {str(i): int(c) for i, c in sorted(counts.items())}, "seed": seed, "note": edit_note})
        report["count_edits"] = history
        new = self._assemble(edited, seed, dict(result.scenario.models), post, plan, report)
        new.report["notes"] = [edit_note] + new.report["notes"]
        if seed != result.scenario.seed:
            new.report["notes"].insert(1, f"re-planned with seed {seed} (the draft came from seed {result.scenario.seed})")
        return new

    def _check_counts(self, groups: Sequence[GroupRecord], counts: Mapping[int, int]) -> list[tuple[str, int, int]]:
        """(label, old, new) for each edited group; GenerationError for unknown groups or counts out of range."""
        if not counts:
            raise GenerationError("no counts to change: give at least one group a new number of people")
        most = self.preset.limits.max_count
        edits = []
        for index, count in counts.items():
            if isinstance(index, bool) or not isinstance(index, int) or not 0 <= index < len(groups):
                raise GenerationError(f"there is no group {index!r}: this scenario has groups 0..{len(groups) - 1} "
                                      f"({', '.join(str(g['label']) for g in groups)})")
            label = str(groups[index]["label"])
            if isinstance(count, bool) or not isinstance(count, int):
                raise GenerationError(f"group '{label}': {count!r} is not a whole number of people")
            if not 1 <= count <= most:
                raise GenerationError(f"group '{label}': {count} people is out of range; preset '{self.preset.name}' "
                                      f"allows 1 to {most} per group")
            edits.append((index, label, int(groups[index]["count"]), count))
        return [edit[1:] for edit in sorted(edits)]

    def _plan_stages(self, inputs: PlanInputs, seed: int, clock: StageClock,
                     cancel: threading.Event | None) -> tuple[PostProcessed, OperationalPlan]:
        """The post-processing and planning stages, shared by `run` and `replan`."""
        world, preset, grid = self.world, self.preset, self.grid
        t0 = clock.begin("postprocess")
        post = postprocess(world, grid, preset, inputs.draft, inputs.selection, seed, inputs.reading,
                           list(inputs.node_names))
        clock.end("postprocess", t0, f"{len(post.agents)} agents")

        t0 = clock.begin("planning")
        plan = plan_operational(world, grid, preset, post, seed, self.robot, planner=self.planner,
                                cache=self.plan_cache, cancel=cancel, reading=inputs.reading)
        check_trees(plan.trees)
        clock.end("planning", t0, f"{len(plan.fields)} field(s)" if plan.fields else "waypoints injected"
                  if preset.planner.enabled else "no planner")
        return post, plan

    def _assemble(self, inputs: PlanInputs, seed: int, models: dict[str, str], post: PostProcessed,
                  plan: OperationalPlan, report: dict[str, Any]) -> GenerationResult:  # Any: generation.json
        """The Scenario and the planned part of the report (groups, exit, notes, goals)."""
        scenario = Scenario(
            world=world_reference(self.world), preset=self.preset.name, prompt=inputs.prompt, seed=int(seed),
            models=models, agents=tuple(plan.agents), robot=plan.robot,
            fields={fid: f"fields/{fid}.npz" for fid in sorted(plan.fields)}, resolution=self.resolution)
        report = dict(report)
        report["groups"] = group_records(post.groups, inputs.reading)
        report["exit"] = post.exit
        report["exits"] = list(post.exits)  # every exit evacuees use, each person its nearest
        report["notes"] = post.notes + plan.notes
        report["grounding"] = grounding_report(inputs.reading, post.groups, post.agents, self.world,
                                               post.notes + plan.notes, robot=plan.robot,
                                               sentence=inputs.sentence or inputs.reading,
                                               walking_speed=self.preset.max_vel,
                                               routes=planned_routes(plan.agents, plan.trees, planning_mode(
                                                   self.preset.velocity, self.preset.planner.enabled))).to_dict()
        report["goals"] = [list(p) for p in post.goals]
        return GenerationResult(scenario, plan.trees, plan.fields, self.grid, report, inputs)
