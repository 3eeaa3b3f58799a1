"""The generation pipeline: prompt -> RoIs -> retrieved nodes -> draft -> trees -> planned trees -> Scenario.

    pipeline = GenerationPipeline(world, preset, llm_roi, llm_bt, retriever)
    result = pipeline.run("Ten patients queue at the pharmacy counter", seed=0, on_event=print, cancel=event)
    write_bundle(result, "out/pharmacy")

`run` is safe to call from a worker thread: progress comes back as plain dataclass events through
`on_event` (called in the caller's thread), and `cancel` (a threading.Event) is checked between
stages, between agents while planning, and during generation (the LLM stops within a second).
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from grove_tui.engine.bt.xml import BTError, parse_tree_text
from grove_tui.engine.grid import OccupancyGrid, build_grid
from grove_tui.engine.paths import worlds_dir
from grove_tui.engine.planner import PlanCache, ThetaStarPlanner
from grove_tui.engine.planning import PlanningCancelled, RobotRequest, plan_operational
from grove_tui.engine.postprocess import check_population, postprocess
from grove_tui.engine.presets import GenerationError, Preset, PromptError
from grove_tui.engine.quantities import extract_quantities
from grove_tui.engine.rois import RoIMatcher, describe_selection, refine_with_model, select_rois
from grove_tui.engine.scenario import Scenario
from grove_tui.engine.synthesis import describe_documents, draft_summary, prepare_request, synthesize
from grove_tui.engine.velocity_field import VelocityField
from grove_tui.models.errors import GenerationCancelled

STAGES = ("rois", "retrieval", "synthesis", "postprocess", "planning")
MAX_PROMPT_CHARS = 2000

__all__ = ["GenerationCancelled", "GenerationError", "GenerationPipeline", "GenerationResult", "STAGES",
           "StageFinished", "StageStarted", "TokenStreamed"]


@dataclass(frozen=True)
class StageStarted:
    stage: str


@dataclass(frozen=True)
class StageFinished:
    stage: str
    seconds: float
    prompt_tokens: int = 0
    completion_tokens: int = 0
    detail: str = ""


@dataclass(frozen=True)
class TokenStreamed:
    stage: str
    text: str


Event = StageStarted | StageFinished | TokenStreamed


@dataclass
class GenerationResult:
    scenario: Scenario
    trees: dict[str, str]  # relative path ("trees/agent_1.xml") -> BT XML
    fields: dict[str, VelocityField]
    grid: OccupancyGrid
    report: dict[str, Any] = field(default_factory=dict)


def world_reference(world: Any) -> str:
    """How a scenario names its world: the shipped name, or the path of a user's world file."""
    source = getattr(world, "source", None)
    if source is None:
        return world.name
    source = Path(source)
    try:
        if source.resolve().parent == worlds_dir().resolve():
            return source.stem
    except OSError:
        pass
    return str(source)


def _model_name(llm: Any) -> str:
    path = getattr(llm, "path", None)
    return Path(path).name if path is not None else type(llm).__name__


class GenerationPipeline:
    """One world and preset, models loaded once; `run` many prompts."""

    def __init__(self, world: Any, preset: Preset, llm_roi: Any | None, llm_bt: Any, retriever: Any,
                 resolution: float | None = None, robot: RobotRequest | None = None,
                 plan_cache: PlanCache | None = None, embed: Callable[[list[str]], Any] | None = None,
                 max_tokens: int = 512) -> None:
        self.world = world
        self.preset = preset
        self.llm_roi = llm_roi
        self.llm_bt = llm_bt
        self.retriever = retriever
        self.resolution = float(resolution or preset.planner.resolution)
        self.robot = robot
        self.plan_cache = plan_cache or PlanCache()
        self.matcher = RoIMatcher(world, embed)
        self.max_tokens = max_tokens
        self._grid: OccupancyGrid | None = None
        self._planner: ThetaStarPlanner | None = None

    @property
    def grid(self) -> OccupancyGrid:
        if self._grid is None:
            self._grid = build_grid(self.world, resolution=self.resolution, inflation=self.preset.planner.inflation)
        return self._grid

    @property
    def planner(self) -> ThetaStarPlanner:
        if self._planner is None:
            self._planner = ThetaStarPlanner(self.grid)
        return self._planner

    def run(self, prompt: str, seed: int = 0, on_event: Callable[[Event], None] | None = None,
            cancel: threading.Event | None = None) -> GenerationResult:
        emit = on_event or (lambda event: None)
        prompt = " ".join((prompt or "").split())
        if not prompt:
            raise PromptError("the prompt is empty: describe the people and what they do")
        if len(prompt) > MAX_PROMPT_CHARS:
            raise PromptError(f"the prompt is {len(prompt)} characters long; keep it under {MAX_PROMPT_CHARS}")
        preset, world = self.preset, self.world
        stages: dict[str, dict[str, Any]] = {}
        started = time.perf_counter()

        def begin(stage: str) -> float:
            if cancel is not None and cancel.is_set():
                raise GenerationCancelled(f"generation cancelled before {stage}")
            emit(StageStarted(stage))
            return time.perf_counter()

        def end(stage: str, t0: float, detail: str, prompt_tokens: int = 0, completion_tokens: int = 0) -> None:
            seconds = time.perf_counter() - t0
            stages[stage] = {"seconds": round(seconds, 4), "prompt_tokens": prompt_tokens,
                             "completion_tokens": completion_tokens}
            emit(StageFinished(stage, seconds, prompt_tokens, completion_tokens, detail))

        t0 = begin("rois")
        quantities = extract_quantities(prompt)
        selection = select_rois(world, preset, prompt, self.matcher)
        roi_tokens = (0, 0)
        if self.llm_roi is not None and preset.guided:
            selection, *roi_tokens = refine_with_model(world, preset, prompt, selection, self.llm_roi, seed, cancel)
        check_population(world, self.grid, preset, selection, quantities)
        end("rois", t0, ", ".join(selection.zones), *roi_tokens)

        t0 = begin("retrieval")
        if preset.retrieval_filter is not None and preset.retrieval_k > 0:
            retrieved = self.retriever.retrieve(prompt, preset.retrieval_filter, k=preset.retrieval_k)
        else:
            retrieved = []
        request = prepare_request(preset, selection, retrieved, prompt, quantities, self.retriever.documents_for)
        end("retrieval", t0, ", ".join(d.name for d in request.documents))

        t0 = begin("synthesis")
        on_token = (lambda text: emit(TokenStreamed("synthesis", text))) if on_event else None
        synthesis = synthesize(self.llm_bt, request, preset, seed, on_token=on_token, cancel=cancel,
                               max_tokens=self.max_tokens)
        end("synthesis", t0, f"{len(synthesis.draft.groups)} group(s), {synthesis.attempts} attempt(s)",
            synthesis.prompt_tokens, synthesis.completion_tokens)

        t0 = begin("postprocess")
        grid = self.grid
        post = postprocess(world, grid, preset, synthesis.draft, quantities, selection, seed, prompt, request.node_names)
        end("postprocess", t0, f"{len(post.agents)} agents")

        t0 = begin("planning")
        try:
            plan = plan_operational(world, grid, preset, post, seed, self.robot, planner=self.planner,
                                    cache=self.plan_cache, cancel=cancel)
        except PlanningCancelled:
            raise GenerationCancelled("generation cancelled during planning") from None
        for rel, xml in plan.trees.items():
            try:
                parse_tree_text(xml, rel)
            except BTError as exc:
                raise GenerationError(f"generated tree failed validation against the node manifest: {exc}") from None
        end("planning", t0, f"{len(plan.fields)} field(s)" if plan.fields else "waypoints injected"
            if preset.planner.enabled else "no planner")

        models = {"bt": _model_name(self.llm_bt)}
        if self.llm_roi is not None:
            models["roi"] = _model_name(self.llm_roi)
        scenario = Scenario(
            world=world_reference(world), preset=preset.name, prompt=prompt, seed=int(seed), models=models,
            agents=tuple(plan.agents), robot=plan.robot,
            fields={fid: f"fields/{fid}.npz" for fid in sorted(plan.fields)}, resolution=self.resolution)
        report = {
            "world": scenario.world, "preset": preset.name, "prompt": prompt, "seed": int(seed), "models": models,
            "stages": stages,
            "total_seconds": round(time.perf_counter() - started, 4),
            "prompt_tokens": synthesis.prompt_tokens, "completion_tokens": synthesis.completion_tokens,
            "quantities": [{"phrase": q.phrase, "count": q.count, "noun": q.noun, "exact": q.exact} for q in quantities],
            "selected_rois": describe_selection(selection), "zones": selection.zones, "named_zones": selection.named_zones,
            "retrieved": [{"name": r.name, "kind": r.kind, "score": r.score, "nodes": list(r.nodes)} for r in retrieved],
            "documents": describe_documents(request.documents), "offered_nodes": request.node_names,
            "draft": draft_summary(synthesis.draft), "draft_text": synthesis.text,
            "attempts": synthesis.attempts, "draft_errors": synthesis.errors,
            "first_token_seconds": None if synthesis.first_token_seconds is None else round(synthesis.first_token_seconds, 4),
            "groups": [{"label": g.label, "count": g.count, "spawn": g.spawn, "members": g.member_ids,
                        "field": g.field_id} for g in post.groups],
            "exit": post.exit, "notes": post.notes + plan.notes,
            "goals": [list(p) for p in post.goals],
        }
        return GenerationResult(scenario, plan.trees, plan.fields, grid, report)
