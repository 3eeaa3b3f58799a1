"""The one application layer: every front end (the app, every `grove` subcommand, batch, evaluation and
the Gym environment) goes through a `GroveSession`, so the same world, preset, prompt, seed and models give
the same bundle whichever way it was asked for.

What only the app needs is arguments of the same API, not another class: progress (`on_event`,
`on_status`, `on_progress` callbacks), cancellation (`cancel` events), a generation with no output folder
(a fresh run folder under `runs_dir`), the stage "loading" (`show_loading`), the warm-up ETAs kept in the
data dir and the model processes' niceness (`GroveSession.for_app`). The app's Textual workers call these
methods from their threads; the session never touches a widget.

(`grove understanding` generates its scenario sample through it too.) A session holds what is expensive and shared: the models, loaded once per role (roles naming the
same file share one instance), the retriever, worlds and presets, and one generation pipeline per
(world, preset, robot request). The RoI model is used the same way on every path: the `roi` role's
model (by default the embedded one, like `bt`) refines ambiguous place mentions in every
generation, and the scenario records it.

Heavy modules (the pipeline, llama.cpp, ChromaDB, torch, numba) are imported inside the methods
that need them, so a front end opens before they load.
"""

from __future__ import annotations

import json
import os
import threading
import time
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import asdict, dataclass, field, is_dataclass
from pathlib import Path, PurePosixPath
from typing import TYPE_CHECKING, Any, TypedDict

from grove_tui.errors import (
    EMPTY_PROMPT_HINT,
    LONG_PROMPT_HINT,
    EXIT_CANCELLED,
    EXIT_MODEL_ERROR,
    BadInputError,
    Cancelled,
    ContextTooSmallError,
    EvalError,
    GroveError,
    PromptError,
    RuntimeFailure,
)
# The values the façade's callers build and receive, handed out here so a front end needs no pipeline
# import: the robot request of a ScenarioRequest and the progress events `on_event` gets. Both modules are
# plain dataclasses, cheap to import.
from grove_tui.generation.events import AttemptStarted as AttemptStarted
from grove_tui.generation.events import Event as Event
from grove_tui.generation.events import StageFinished as StageFinished
from grove_tui.generation.events import StageStarted as StageStarted
from grove_tui.generation.events import TokenStreamed as TokenStreamed
from grove_tui.generation.requests import MAX_PROMPT_CHARS
from grove_tui.generation.requests import RobotRequest as RobotRequest

if TYPE_CHECKING:
    from grove_tui.analysis.empirical import EmpiricalResult
    from grove_tui.analysis.evaluation import CaseResult, EvalCase
    from rich.table import Table
    from rich.text import Text

    from grove_tui.analysis.live_metrics import LiveMetrics
    from grove_tui.analysis.metrics import MetricsReport
    from grove_tui.analysis.outcomes import OutcomeChecker
    from grove_tui.analysis.rimea import RimeaResult
    from grove_tui.analysis.understanding import ReadingScore, ScenarioScore, UnderstandingCase
    from grove_tui.bt.format.document import TreeDocument, TreeFiles
    from grove_tui.bt.format.manifest import NodeSpec
    from grove_tui.bt.format.xml import BTProblem
    from grove_tui.generation.pipeline import GenerationPipeline, GenerationResult
    from grove_tui.generation.refine import Refinement
    from grove_tui.generation.retrieval import EvalResult as RetrievalEval
    from grove_tui.generation.retrieval import NodeRetriever
    from grove_tui.generation.presets import Preset
    from grove_tui.llm.registry import FoundModel, ModelChoice
    from grove_tui.scenario.model import Scenario
    from grove_tui.services.exporting import ExportedFile, Exporter
    from grove_tui.services.jobs import BatchJob, JobProblem, Variation
    from grove_tui.services.runs import RunInfo
    from grove_tui.simulation.simulation import Simulation
    from grove_tui.world import World
    from grove_tui.world.loader import WorldProblem
    import numpy as np

    from grove_tui.crowd.sfm import SFMParams
    from grove_tui.jsontypes import JSONObject
    from grove_tui.llm.local import LocalLLM
    from grove_tui.scenario.report import GroundingReport
    from grove_tui.scenario.events import SimEvent

LLMFactory = Callable[[str, "ModelChoice"], "LocalLLM"]  # (role, choice) -> the model of that role
RetrieverFactory = Callable[[], "NodeRetriever"]
EventSink = Callable[["Event | LoadingProgress"], None]  # a stage Event (StageStarted, TokenStreamed, ...) or loading
MAX_FOLLOWUP_CHARS = 500


@dataclass(frozen=True)
class ScenarioRequest:
    """What a scenario is generated from; equal requests through the same session give equal bundles."""

    world: str  # shipped world name or path to a world YAML
    preset: str
    prompt: str
    seed: int = 0
    robot: RobotRequest | None = None  # None: a robot placed by the pipeline
    variation: Variation | None = None  # which of N variations of the prompt (recorded in generation.json)


def variation_requests(request: ScenarioRequest, count: int) -> list[ScenarioRequest]:
    """The `count` variations of a request: same prompt, seeds derived from its seed (jobs.variation_seed)."""
    from dataclasses import replace

    from grove_tui.services.jobs import Variation, check_variations, variation_seed

    try:
        check_variations(count)
    except ValueError as exc:
        raise BadInputError(str(exc)) from None
    return [replace(request, seed=variation_seed(request.seed, index), variation=Variation(index, count, request.seed))
            for index in range(count)]


@dataclass
class GeneratedScenario:
    """A generation result, the world it was made in, and the bundle written for it."""

    prompt: str
    world_name: str
    preset: str
    seed: int
    world: World
    result: GenerationResult  # scenario, trees, fields, grid, report
    bundle_dir: Path

    @property
    def scenario(self) -> Scenario:
        return self.result.scenario


@dataclass(frozen=True)
class ModelStatus:
    role: str
    file: str
    loaded: bool
    error: str = ""


# How long each warm-up step takes on a machine that never ran one (2 cores, embedded model): the ETA of
# the first warm-up; later ones expect what the step took last time (GroveSession.step_seconds).
FIRST_STEP_SECONDS = {"models": 5.0, "retrieval": 15.0, "reader": 3.0, "planner": 3.0, "prompt": 5.0}


@dataclass(frozen=True)
class WarmUpStatus:
    """One step of GroveSession.warm_up, for a status line: "loading the models…", "ready to generate"."""

    step: str  # "models" | "retrieval" | "reader" | "planner" | "prompt", then "ready" once all have run
    state: str  # "running" | "done" | "failed"
    doing: str  # what the step does, in words
    error: str = ""
    expected_seconds: float = 0.0  # running: how long the step took last time (or on a first run)
    seconds: float = 0.0  # done or failed: how long it took

    @property
    def text(self) -> str:
        if self.state == "running":
            return f"{self.doing}…"
        if self.state == "failed":
            return f"{self.doing}: failed: {self.error}" if self.error else "not ready: a warm-up step failed"
        return self.doing if self.step == "ready" else f"{self.doing}: done"


@dataclass(frozen=True)
class LoadingProgress:
    """An event of the stage "loading" that `generate` runs first when the session is not warm yet: part
    `index` of `parts` starts (the models, the node index and its embedder, the English reader, the
    world's planner, the world and preset's fixed prompt). `expected_seconds` is what it took last time,
    `later_seconds` what the parts after it took: the stage's ETA."""

    part: str
    doing: str
    index: int
    parts: int
    expected_seconds: float
    later_seconds: float


def _warm_reader(world: World | None = None) -> None:
    """spaCy, and with a world the meaning model and the world's place vectors (language/meaning.py)."""
    from grove_tui.language import parser
    from grove_tui.language.places import place_index

    parser.load()
    if world is not None:
        place_index(world).warm_meaning()


@dataclass(frozen=True)
class Models:
    """The model of each role; one object when both roles name the same file."""

    roi: LocalLLM
    bt: LocalLLM


class SimulationSummaryDict(TypedDict):
    """SimulationSummary as JSON holds it (`grove simulate --json`, the batch's records)."""

    sim_seconds: float
    wall_seconds: float
    counters: JSONObject
    wall_penetrations: int
    goal_reach_rate: float | None


@dataclass(frozen=True)
class SimulationSummary:
    sim_seconds: float
    wall_seconds: float
    counters: JSONObject
    wall_penetrations: int
    goal_reach_rate: float | None

    def to_dict(self) -> SimulationSummaryDict:
        return {"sim_seconds": self.sim_seconds, "wall_seconds": self.wall_seconds, "counters": dict(self.counters),
                "wall_penetrations": self.wall_penetrations, "goal_reach_rate": self.goal_reach_rate}


@dataclass(frozen=True)
class BundleMetrics:
    """What `GroveSession.metrics` wrote: metrics.json, and grounding.json when the bundle has a report."""

    metrics: MetricsReport
    metrics_file: Path
    grounding: JSONObject | None = None  # grounding.json as written (JSON; scenario.report.GroundingReport)
    grounding_file: Path | None = None


@dataclass(frozen=True)
class EvaluationRow:
    """One (preset, method) line of an evaluation's summary."""

    preset: str
    method: str
    grounding: float
    plausibility: float
    means: dict[str, float]  # every score column's mean (analysis.evaluation.summarize)


@dataclass(frozen=True)
class UnderstandingReport:
    """What `GroveSession.understanding_report` wrote and its tables: field -> (passed, scored)."""

    paths: list[Path]
    reading: dict[str, tuple[int, int]]
    scenarios: dict[str, tuple[int, int]]
    below_the_bar: list[str]  # the must-show fields that miss their bar, as readable lines


@dataclass(frozen=True)
class JobOutcome:
    """One batch job: its bundle, or the error that stopped it (the batch goes on)."""

    job: BatchJob
    bundle: Path
    generated: GeneratedScenario | None = None
    simulation: SimulationSummary | None = None
    exports: dict[str, Path] = field(default_factory=dict)
    error: GroveError | None = None


# How far below the app's priority the model processes run while the app is open (see
# GroveSession.yield_cpu_to_the_app); 0 leaves them alone.
MODEL_NICENESS = 10
LOWEST_PRIORITY = 19  # the largest niceness POSIX allows


@dataclass(frozen=True)
class PresetInfo:
    name: str
    description: str


class GroveSession:
    """Models loaded once per role; generate, re-plan, simulate, export, evaluate and batch."""

    def __init__(self, *, model: str | None = None, roi_model: str | None = None, bt_model: str | None = None,
                 llm_factory: LLMFactory | None = None, retriever_factory: RetrieverFactory | None = None,
                 runs_dir: Path | None = None, model_niceness: int = 0, remember_step_seconds: bool = False,
                 exporters: list[tuple[str, Exporter]] | None = None) -> None:
        """`runs_dir`: where a generation asked for without an output folder writes (default the data
        dir's runs/); `model_niceness`: how far below this process `yield_cpu_to_the_app` puts the model
        processes; `remember_step_seconds`: keep what each warm-up step took in the data dir (the ETAs);
        `exporters`: the steps of `export_all` (default every format's, services.exporting)."""
        from grove_tui.services.exporting import APP_EXPORTERS

        self._cli_model = model
        self._cli_roi = roi_model
        self._cli_bt = bt_model
        self._llm_factory = llm_factory
        self._retriever_factory = retriever_factory
        self._lock = threading.RLock()  # held only to read or swap state, never while something loads
        self._models_lock = threading.Lock()  # one model load at a time
        self._closes = 0  # how many times close() ran: a load it overtook keeps nothing
        self._warmed: set[str] = set()  # warm-up steps done (keys of _warm_steps)
        # Seconds each warm-up step took last (its ETA next time); the app seeds it from its data dir.
        self.step_seconds: dict[str, float] = {}
        self._models: Models | None = None
        self._model_errors: dict[str, str] = {}
        self._retriever: NodeRetriever | None = None
        self._worlds: dict[str, World] = {}
        # by (world, preset, robot request or "planning-only")
        self._pipelines: dict[tuple[str, str, RobotRequest | str | None], GenerationPipeline] = {}
        self._warm = False
        self._stop_warm_up = threading.Event()  # set by close(): a warm-up still running loads nothing more
        self._runs_dir = runs_dir
        self.model_niceness = model_niceness
        self.exporters = list(APP_EXPORTERS if exporters is None else exporters)
        self._remember_step_seconds = remember_step_seconds
        self._embedder_warm = False
        if remember_step_seconds:  # what each warm-up step took on this machine last time: the app's ETAs
            from grove_tui.services.runs import load_step_seconds

            self.step_seconds.update(load_step_seconds())

    @classmethod
    def for_app(cls, **options: Any) -> GroveSession:  # Any: GroveSession's own keyword arguments, passed on
        """A session as the app holds one: model processes below the app's priority, warm-up ETAs kept."""
        options.setdefault("model_niceness", MODEL_NICENESS)
        options.setdefault("remember_step_seconds", True)
        return cls(**options)

    @property
    def runs_dir(self) -> Path:
        """Where `generate`, `replan` and `refine` write when given no output folder (the app's runs)."""
        if self._runs_dir is None:
            from grove_tui.settings import data_dir

            self._runs_dir = data_dir() / "runs"
        return self._runs_dir

    def new_run_dir(self, name: str) -> Path:
        """A folder under `runs_dir` named `name` (with -2, -3... when taken), not created yet."""
        from grove_tui.services.runs import free_folder

        return free_folder(self.runs_dir, name)

    def recent_runs(self, limit: int = 50) -> list[RunInfo]:
        """Bundles under the runs folder, newest first; a broken one is listed with what is wrong."""
        from grove_tui.services.runs import list_runs

        return list_runs(self.runs_dir, limit)

    def _save_step_seconds(self) -> None:
        if self._remember_step_seconds:
            from grove_tui.services.runs import save_step_seconds

            save_step_seconds(self.step_seconds)

    # inputs -------------------------------------------------------------------------------------------
    def list_worlds(self) -> list[str]:
        from grove_tui.world import list_worlds

        return list(list_worlds())

    def load_world(self, name: str) -> World:
        """A world by shipped name or path, loaded once per session."""
        with self._lock:
            world = self._worlds.get(name)
        if world is None:
            from grove_tui.world import load_world

            world = load_world(name)
            with self._lock:
                self._worlds[name] = world
        return world

    def check_world_file(self, name_or_path: str) -> tuple[Path, World | None, list[WorldProblem]]:
        """A world YAML (or a shipped name) checked in one parse: (its path, the World when it has no
        problem, every problem with its line). A file that cannot be read at all (missing, not a regular
        file, over the size limit, not UTF-8) raises WorldError, whose hint says what a world file must be."""
        from grove_tui.errors import WorldError
        from grove_tui.world import parse_world, read_world_file
        from grove_tui.world.loader import MAX_WORLD_FILE_BYTES

        try:
            path, text = read_world_file(name_or_path)
        except WorldError as error:
            raise WorldError(error.message, hint="give readable world YAML files (regular, UTF-8, at most "
                             f"{MAX_WORLD_FILE_BYTES >> 20} MB) or shipped names (grove worlds list)") from None
        world, problems = parse_world(text, str(path))
        return path, world, problems

    def world_map(self, world: World, width: int, height: int | None = None) -> tuple[Text, Table]:
        """A world drawn for the terminal `width` columns wide (walls, doors, exits, zone labels,
        entities), and its legend."""
        from grove_tui.world.render import legend, render_world_text

        return render_world_text(world, width, height), legend(world)

    def load_preset(self, name: str) -> Preset:
        from grove_tui.generation.presets import load_preset

        return load_preset(name)

    def presets(self) -> list[PresetInfo]:
        """Every shipped preset with its description (a broken one says why)."""
        from grove_tui.generation.presets import list_presets

        infos = []
        for name in list_presets():
            try:
                infos.append(PresetInfo(name, self.load_preset(name).description))
            except GroveError as exc:
                infos.append(PresetInfo(name, f"(broken: {exc})"))
        return infos

    def check_request(self, request: ScenarioRequest) -> tuple[World, Preset]:
        """World and preset of a request, and a non-empty prompt, before any model loads."""
        if not request.prompt or not request.prompt.strip():
            raise PromptError("the prompt is empty: describe the people and what they do", hint=EMPTY_PROMPT_HINT)
        folded = " ".join(request.prompt.split())
        if len(folded) > MAX_PROMPT_CHARS:
            raise PromptError(f"the prompt is {len(folded)} characters long; keep it under {MAX_PROMPT_CHARS}",
                              hint=LONG_PROMPT_HINT)
        try:
            request.prompt.encode("utf-8")
        except UnicodeEncodeError as exc:
            # A lone surrogate (JSON's "\ud800", or bytes that are not UTF-8 on the command line) reaches
            # no parser: spaCy, the model and the dataset index all refuse to encode it.
            raise PromptError(f"the prompt is not Unicode text: character {exc.start + 1} is a lone surrogate "
                              f"(\\u{ord(request.prompt[exc.start]):04x})",
                              hint="Give the prompt as UTF-8 text.") from None
        return self.load_world(request.world), self.load_preset(request.preset)

    def unsure(self, request: ScenarioRequest) -> list[str]:
        """Questions about what the reader is unsure of in the request's sentence ("'the big meeting
        room' start: boardroom or meeting_room?"), before any model loads; [] when it is sure of all.

        The app asks them before generating; `grove generate --strict` refuses with them."""
        from grove_tui.generation.reconcile import reading_questions
        from grove_tui.language.reading import read_prompt

        world, _preset = self.check_request(request)
        return reading_questions(read_prompt(" ".join(request.prompt.split()), world, seed=request.seed))

    # models ---------------------------------------------------------------------------------------------
    @property
    def model_options(self) -> tuple[str | None, str | None, str | None]:
        """The (model, roi_model, bt_model) this session was made with, to make an equal one elsewhere (a Ray worker)."""
        return self._cli_model, self._cli_roi, self._cli_bt

    def model_choices(self) -> dict[str, ModelChoice]:
        from grove_tui.llm.registry import resolve_models

        return dict(resolve_models(self._cli_roi, self._cli_bt, self._cli_model))

    def list_models(self) -> tuple[list[FoundModel], dict[str, ModelChoice] | str]:
        """Every model in sight (models dir, embedded, this session's chosen paths) with its metadata and
        the roles using it; the role resolution, or the text of the error that stopped it (`grove models list`)."""
        from grove_tui.llm.registry import list_models

        return list_models(self._cli_roi, self._cli_bt, self._cli_model)

    def pull_model(self, name: str, *, endpoint: str | None = None, force: bool = False,
                   on_start: Callable[[str, int], None] | None = None,
                   on_progress: Callable[[int, int], None] | None = None) -> Path:
        """Download an official catalog GGUF into the models dir, verified (size, sha256, GGUF header);
        `on_start(url, bytes)` before the download, `on_progress(received, total)` during it."""
        from grove_tui.llm.pull import CATALOG, download_url, pull_model

        entry = CATALOG.get(name)
        if entry is None:
            raise BadInputError(f"unknown model {name!r}; available: {', '.join(CATALOG)}")
        if on_start is not None:
            on_start(download_url(entry, endpoint), entry.size)
        return pull_model(name, endpoint=endpoint, force=force, on_progress=on_progress)

    def model_status(self) -> list[ModelStatus]:
        """Each role's file and whether it is loaded; a role that cannot be resolved shows its error."""
        from grove_tui.errors import describe_error

        try:
            choices = self.model_choices()
        except GroveError as exc:
            problem = describe_error(exc).text
            return [ModelStatus("roi", "?", False, problem), ModelStatus("bt", "?", False, problem)]
        with self._lock:
            loaded = {"roi": self._models.roi, "bt": self._models.bt} if self._models is not None else {}
            return [ModelStatus(role, choice.path.name, _is_running(loaded.get(role)), self._model_errors.get(role, ""))
                    for role, choice in choices.items()]

    def load_models(self) -> Models:
        """Load each role's model once; roles naming the same file share the instance.

        Loading takes seconds, under its own lock: the session's lock is only taken to look at what is
        loaded, so the worlds, the model status and `close` never wait for a model to load. A load that
        `close` overtook closes what it loaded and raises Cancelled.
        """
        with self._lock:
            if self._models is not None:
                return self._models
        with self._models_lock:
            with self._lock:
                if self._models is not None:
                    return self._models
                closes = self._closes
            by_path: dict[Path, LocalLLM] = {}
            loaded: dict[str, LocalLLM] = {}
            for role, choice in self.model_choices().items():
                key = choice.path.resolve()
                try:
                    if key not in by_path:
                        by_path[key] = self._make_llm(role, choice)
                except GroveError as exc:
                    with self._lock:
                        self._model_errors[role] = str(exc)
                    for llm in by_path.values():
                        _close(llm)
                    raise
                loaded[role] = by_path[key]
                with self._lock:
                    self._model_errors.pop(role, None)
            with self._lock:
                if self._closes == closes:
                    self._models = Models(roi=loaded["roi"], bt=loaded["bt"])
                    return self._models
            for llm in by_path.values():  # the session was closed meanwhile: keep nothing running
                _close(llm)
            raise Cancelled("the session was closed while its models loaded")

    def _make_llm(self, role: str, choice: ModelChoice) -> LocalLLM:
        if self._llm_factory is not None:
            return self._llm_factory(role, choice)
        from grove_tui.llm.local import LocalLLM

        # No fixed thread count: every request takes the idle cores of that moment (cpu.py).
        llm = LocalLLM(choice.path, role=role, n_ctx=choice.n_ctx)
        llm.start()  # loads the weights in the model's worker process now, not at the first prompt
        return llm

    # warm start -----------------------------------------------------------------------------------------
    def _warm_steps(self, world: str | None, preset: str | None) -> list[tuple[str, str, str, Callable[[], object]]]:
        """(key, step, what it does, how) of everything a first generation would otherwise load itself."""
        steps: list[tuple[str, str, str, Callable[[], object]]] = [
            ("models", "models", "loading the models", self.load_models),
            ("retrieval", "retrieval", "loading the node index and its embedder", self.warm_up_retrieval),
            (f"reader:{world}" if world is not None else "reader", "reader", "loading the English reader",
             lambda: _warm_reader(self.load_world(world) if world is not None else None)),
        ]
        if world is not None and preset is not None:
            steps.append((f"planner:{world}:{preset}", "planner", f"preparing {world}'s map and planner",
                          lambda: self._warm_planner(world, preset)))
            steps.append((f"prompt:{world}:{preset}", "prompt", f"reading {world}/{preset}'s fixed prompt into the model",
                          lambda: self._warm_prefix(world, preset)))
        return steps

    def expected_seconds(self, step: str) -> float:
        """How long a warm-up step took last time (this session, or `step_seconds` as the caller seeded it)."""
        with self._lock:
            return self.step_seconds.get(step, FIRST_STEP_SECONDS.get(step, 2.0))

    def _run_step(self, key: str, step: str, run: Callable[[], object]) -> float:
        started = time.perf_counter()
        run()
        seconds = time.perf_counter() - started
        with self._lock:
            self.step_seconds[step] = round(seconds, 2)
            self._warmed.add(key)
        return seconds

    def warm_up(self, world: str | None = None, preset: str | None = None, *,
                on_status: Callable[[WarmUpStatus], None] | None = None) -> list[WarmUpStatus]:
        """Load now what the first generation would otherwise load: the models, the node index and its
        embedder, the English reader, and (given a world and preset) their pipeline's grid and planner.

        Each step reports a WarmUpStatus (`running` with the seconds it is expected to take, then `done`
        or `failed` with the error) through `on_status`; a step that fails does not stop the next ones
        (the generation reports it again). Safe to run beside a generation: each part loads under its
        own lock, once (a generation that starts before the warm-up is done loads what is missing as
        its stage "loading", `prepare`).
        """
        statuses: list[WarmUpStatus] = []
        for key, step, doing, run in self._warm_steps(world, preset):
            if self._stop_warm_up.is_set():
                return statuses
            if on_status is not None:
                on_status(WarmUpStatus(step, "running", doing, expected_seconds=self.expected_seconds(step)))
            started = time.perf_counter()
            try:
                seconds = self._run_step(key, step, run)
            except GroveError as exc:
                status = WarmUpStatus(step, "failed", doing, str(exc), seconds=time.perf_counter() - started)
            except Exception as exc:  # noqa: BLE001 - any engine failure is reported on the status line, not raised
                status = WarmUpStatus(step, "failed", doing, f"{type(exc).__name__}: {exc}",
                                      seconds=time.perf_counter() - started)
            else:
                status = WarmUpStatus(step, "done", doing, seconds=seconds)
            statuses.append(status)
            if on_status is not None:
                on_status(status)
        with self._lock:
            self._warm = all(status.state == "done" for status in statuses)
        self._save_step_seconds()
        if on_status is not None:
            on_status(WarmUpStatus("ready", "done" if self._warm else "failed", "ready to generate"))
        return statuses

    def prepare(self, world: str, preset: str, *, on_event: EventSink | None = None,
                cancel: threading.Event | None = None) -> None:
        """Load what a generation in `world` with `preset` needs and is not loaded yet, as the stage
        "loading" (StageStarted, a LoadingProgress per part, StageFinished); nothing when all is warm.

        A part the warm-up is loading at the same moment is waited for under its lock, not loaded twice.
        """
        with self._lock:
            missing = [step for step in self._warm_steps(world, preset) if step[0] not in self._warmed]
        if not missing:
            return
        emit = on_event or (lambda event: None)
        emit(StageStarted("loading"))
        started = time.perf_counter()
        expected = [self.expected_seconds(step) for _key, step, _doing, _run in missing]
        for index, (key, step, doing, run) in enumerate(missing):
            if cancel is not None and cancel.is_set():
                raise Cancelled("generation cancelled while loading")
            emit(LoadingProgress(step, doing, index + 1, len(missing), expected[index], sum(expected[index + 1:])))
            self._run_step(key, step, run)
        parts = ", ".join(step for _key, step, _doing, _run in missing)
        emit(StageFinished("loading", time.perf_counter() - started, 0, 0, f"loaded {parts}"))

    def start_warm_up(self, world: str | None = None, preset: str | None = None, *,
                      on_status: Callable[[WarmUpStatus], None] | None = None) -> threading.Thread:
        """`warm_up` in a background thread (the app and a batch start it and go on)."""
        self._stop_warm_up.clear()
        thread = threading.Thread(target=self.warm_up, args=(world, preset), kwargs={"on_status": on_status},
                                  name="grove-warm-up", daemon=True)
        thread.start()
        return thread

    def stop_warm_up(self, thread: threading.Thread, *, wait: bool = True) -> None:
        """Stop a background warm-up after the step it is in (and wait for that step): nothing this session
        started keeps loading once its caller is done (a batch with nothing left to run, a failed one)."""
        self._stop_warm_up.set()
        if wait:
            thread.join()

    @property
    def warm(self) -> bool:
        """Whether a warm-up finished with every step done."""
        with self._lock:
            return self._warm

    def warm_up_retrieval(self) -> None:
        """Open the node index and load the embedding model, so the first retrieval loads neither."""
        retriever = self.retriever()
        if self._retriever_factory is not None:
            return  # a test's retriever: nothing of the real index or embedder to load
        from grove_tui.generation.retrieval import embed_query

        retriever.ensure_index()
        embed_query("people walk to the exit")  # imports torch, loads the model and its traced query encoder
        self._embedder_warm = True

    def embedder_ready(self) -> bool:
        """Whether retrieval runs without first loading the embedding model (warmed, or used once)."""
        return self._embedder_warm or self._retriever_factory is not None

    def yield_cpu_to_the_app(self) -> list[int]:
        """Run the model processes `model_niceness` steps below this process's priority; the pids changed.

        llama.cpp sizes its threads to the cores free when its process starts and spins at its
        barriers, so while it writes it holds every core and the app's key handling waits for a time
        slice (0.4-0.8 s per key in issue 21). One step of niceness is ~1.25x less CPU weight, so at +10
        the app's thread takes a core within the scheduler's latency whenever it has work, and the
        model loses only the little CPU the app uses. Niceness cannot be lowered again without
        privileges, so this is only done for the session's own model processes, and is idempotent.
        """
        if self.model_niceness <= 0 or not hasattr(os, "setpriority"):
            return []
        target = min(os.getpriority(os.PRIO_PROCESS, 0) + self.model_niceness, LOWEST_PRIORITY)
        changed = []
        for llm in self.loaded_models():
            pid = getattr(llm, "worker_pid", None)
            if not isinstance(pid, int):
                continue
            try:
                if os.getpriority(os.PRIO_PROCESS, pid) < target:
                    os.setpriority(os.PRIO_PROCESS, pid, target)
                    changed.append(pid)
            except OSError:  # the process ended (cancelled, crashed) between the lookup and the call
                continue
        return changed

    def _warm_planner(self, world: str, preset: str) -> None:
        from grove_tui.errors import PlanningError

        with self._lock:
            if self._models is None or self._stop_warm_up.is_set():
                return  # the models failed (already reported) or the session closed: build no pipeline now
        planner = self.pipeline(world, preset).planner
        free = planner.grid.free_cells()
        if len(free) < 2:
            return
        # One short plan loads the numba kernels (compiled into the cache dir on the first run ever).
        first, last = free[0], free[min(len(free) - 1, 50)]
        try:
            planner.plan(planner.grid.cell_to_world(*first), planner.grid.cell_to_world(*last))
        except PlanningError:
            pass  # two cells with no path between them have still loaded the kernels

    def _warm_prefix(self, world: str, preset: str) -> None:
        from grove_tui.generation.synthesis import warm_prefix

        with self._lock:
            if self._models is None or self._stop_warm_up.is_set():
                return
        pipeline = self.pipeline(world, preset)
        if pipeline.llm_bt is not None:
            warm_prefix(pipeline.llm_bt, pipeline.preset, pipeline.world,
                        getattr(pipeline.retriever, "documents_named", None))

    def retriever(self) -> NodeRetriever:
        with self._lock:
            if self._retriever is None:
                if self._retriever_factory is not None:
                    self._retriever = self._retriever_factory()
                else:
                    from grove_tui.generation.retrieval import NodeRetriever

                    self._retriever = NodeRetriever()
            return self._retriever

    def node_retriever(self, node_db: Path | None = None, index_dir: Path | None = None) -> NodeRetriever:
        """A retriever over a node database and its index (default: the shipped node_db, the cache's
        index), built anew: `grove rag build|query|eval` point it at other folders."""
        from grove_tui.generation.retrieval import NodeRetriever

        return NodeRetriever(node_db_dir=node_db, index_dir=index_dir)

    def sync_node_documents(self, node_db: Path | None = None, *,
                            check_only: bool = False) -> tuple[list[str], list[str], list[str]]:
        """node_db/nodes/<Name>.md written from the node manifest (nothing written with `check_only`):
        (documents written, documents removed, problems left)."""
        from grove_tui import paths
        from grove_tui.generation.node_docs import check_node_documents, sync_node_documents

        root = node_db or paths.node_db_dir()
        if check_only:
            return [], [], check_node_documents(root)
        written, removed = sync_node_documents(root)
        return written, removed, check_node_documents(root)

    def evaluate_retrieval(self, retriever: NodeRetriever, k: int = 8,
                           cases: Path | None = None) -> RetrievalEval:
        """Recall@k of `retriever` on a labelled set (default: its node_db's eval.yaml)."""
        from grove_tui.generation.retrieval import evaluate, load_eval_set

        labelled = load_eval_set(cases if cases is not None else retriever.node_db_dir / "eval.yaml")
        return evaluate(retriever, labelled, k)

    def loaded_models(self) -> list[LocalLLM]:
        """The model instances loaded so far (each once), without loading any."""
        with self._lock:
            if self._models is None:
                return []
            return list({id(m): m for m in (self._models.roi, self._models.bt)}.values())

    def close(self) -> None:
        """Stop the model processes (and a background warm-up); the session loads them again if used after.

        Never waits for a model still loading (that load closes its own when it ends)."""
        self._stop_warm_up.set()
        with self._lock:
            models, self._models = self._models, None
            self._closes += 1
            self._pipelines.clear()
        if models is not None:
            for llm in {id(m): m for m in (models.roi, models.bt)}.values():
                _close(llm)

    def __enter__(self) -> GroveSession:
        return self

    def __exit__(self, *exc_info: object) -> None:
        self.close()

    # generation -----------------------------------------------------------------------------------------
    def pipeline(self, world_name: str, preset_name: str, robot: RobotRequest | None = None) -> GenerationPipeline:
        """The pipeline of a world and preset (and robot request), built once per session."""
        from grove_tui.generation.pipeline import GenerationPipeline

        key = (world_name, preset_name, robot)
        with self._lock:
            pipeline = self._pipelines.get(key)
        if pipeline is None:
            world, preset = self.load_world(world_name), self.load_preset(preset_name)
            models = self.load_models()
            pipeline = GenerationPipeline(world, preset, models.roi, models.bt, self.retriever(), robot=robot)
            with self._lock:
                pipeline = self._pipelines.setdefault(key, pipeline)
        return pipeline

    def generate(self, request: ScenarioRequest, out_dir: str | Path | None = None, *, overwrite: bool = False,
                 on_event: EventSink | None = None, cancel: threading.Event | None = None,
                 show_loading: bool = False) -> GeneratedScenario:
        """Generate the request's scenario and write its bundle to `out_dir` (an old bundle there is replaced);
        without `out_dir`, to a new folder under `runs_dir` named by time, prompt and seed.

        `show_loading`: first load what is not loaded yet as the stage "loading" with an ETA (`prepare`),
        so a generation asked before the warm-up is done is never silent (the app); the command line
        loads as it goes."""
        from grove_tui.files import check_output_dir
        from grove_tui.scenario.bundle import WHAT, is_bundle
        from grove_tui.services.runs import slug

        stamp = time.strftime("%Y%m%d-%H%M%S")
        try:
            world, _preset = self.check_request(request)
            if show_loading:
                self.prepare(request.world, request.preset, on_event=on_event, cancel=cancel)
            if out_dir is None:
                out_dir = self.new_run_dir(f"{stamp}-{slug(request.prompt)}-{request.seed}")
            # Before the model runs: a refused or unwritable folder must not cost a generation.
            check_output_dir(out_dir, owned=is_bundle, what=WHAT, overwrite=overwrite)
            pipeline = self.pipeline(request.world, request.preset, request.robot)
            result = pipeline.run(request.prompt, seed=request.seed, on_event=on_event, cancel=cancel)
        finally:
            self._save_step_seconds()
        self._embedder_warm = True  # retrieval ran: the embedding model is loaded for the next run
        if request.variation is not None:
            result.report["variation"] = request.variation.to_dict(request.prompt)
        bundle = self.write_bundle(result, out_dir, overwrite=overwrite)
        return GeneratedScenario(request.prompt, request.world, request.preset, request.seed, world, result, bundle)

    def write_bundle(self, result: GenerationResult, out_dir: str | Path, *, overwrite: bool = False) -> Path:
        from grove_tui.scenario.bundle import write_bundle

        return Path(write_bundle(result, Path(out_dir), overwrite=overwrite))

    def replan(self, generated: GeneratedScenario, counts: dict[int, int], out_dir: str | Path | None = None, *,
               seed: int | None = None, on_event: EventSink | None = None,
               cancel: threading.Event | None = None) -> GeneratedScenario:
        """The same draft with new head counts (group index -> count), re-planned without a model call,
        written to `out_dir` (without it, a new folder under `runs_dir`); `generated` is left as it was.

        A scenario that keeps no draft (opened from a bundle, or refined) changes its counts as a
        refinement: the other groups stay byte for byte, and the edit is a step of its history.
        An error's hint is about the counts, which are what changed here."""
        from grove_tui.errors import GenerationError
        from grove_tui.services.runs import slug

        if out_dir is None:
            stamp = time.strftime("%Y%m%d-%H%M%S")
            out_dir = self.new_run_dir(f"{stamp}-{slug(generated.prompt)}-"
                                       f"{generated.seed if seed is None else seed}-counts")
        try:
            return self._replan(generated, counts, out_dir, seed=seed, on_event=on_event, cancel=cancel)
        except PromptError as exc:
            exc.hint = "Lower the counts of the groups in that zone, or regenerate with a roomier place."
            raise
        except GenerationError as exc:
            exc.hint = "Change the counts and press Enter again, or Escape to keep the scenario as it is."
            raise

    def _replan(self, generated: GeneratedScenario, counts: dict[int, int], out_dir: str | Path, *,
                seed: int | None, on_event: EventSink | None, cancel: threading.Event | None) -> GeneratedScenario:
        from grove_tui.generation.pipeline import GenerationPipeline

        if generated.result.inputs is None and generated.result.report.get("groups"):
            return self.refine(generated, self._count_refinement(generated, counts), out_dir, on_event=on_event,
                               cancel=cancel)
        preset = self.load_preset(generated.preset)
        pipeline = GenerationPipeline(generated.world, preset, None, None, None)
        result = pipeline.replan(generated.result, counts, seed=seed, on_event=on_event, cancel=cancel)
        bundle = self.write_bundle(result, out_dir)
        return GeneratedScenario(generated.prompt, generated.world_name, generated.preset, result.scenario.seed,
                                 generated.world, result, bundle)

    # refinement -----------------------------------------------------------------------------------------
    def open_bundle(self, bundle_dir: str | Path) -> GeneratedScenario:
        """A saved bundle as a generation's result (no draft: its counts re-plan through `refine`)."""
        from grove_tui.generation.pipeline import GenerationResult
        from grove_tui.scenario.bundle import REPORT_FILE, load_bundle, load_report, world_source

        bundle_dir = Path(bundle_dir)
        scenario, trees, fields, grid = load_bundle(bundle_dir)
        # A bundle copied without its report still opens; only the timings and groups are missing.
        report = load_report(bundle_dir) if (bundle_dir / REPORT_FILE).is_file() else {}
        world = self.load_world(str(world_source(bundle_dir, scenario)))
        result = GenerationResult(scenario, trees, fields, grid, report)
        return GeneratedScenario(scenario.prompt, scenario.world, scenario.preset, int(scenario.seed), world, result,
                                 bundle_dir)

    def read_refinement(self, generated: GeneratedScenario, sentence: str, *,
                        choices: Sequence[int] = ()) -> Refinement:
        """What a follow-up would do to a scenario, as a diff, before anything runs (no model).

        `choices` settle ambiguous group names in order ("the nurse" with two nurse groups), each the
        index of the group meant. Raises AmbiguousEditError (with the choices) while one is unsettled,
        EditError when the follow-up changes nothing."""
        from grove_tui.generation.refine import plan_refinement
        from grove_tui.generation.scene import scene_of
        from grove_tui.language.followup import read_followup

        sentence = " ".join((sentence or "").split())
        if not sentence:
            raise PromptError("the follow-up is empty: say what to add, change or remove")
        if len(sentence) > MAX_FOLLOWUP_CHARS:
            raise PromptError(f"the follow-up is {len(sentence)} characters long; keep it under {MAX_FOLLOWUP_CHARS}")
        scene = scene_of(generated.result, generated.world)
        last = [g.index for g in scene.groups if scene.steps and (g.asked_by == scene.steps or
                                                                  scene.steps in g.changed_by)]
        edit = read_followup(sentence, generated.world, [g.reading for g in scene.groups],
                             has_robot=generated.scenario.robot is not None, seed=int(generated.seed), last=last)
        for choice in choices:
            pending = edit.ambiguities()
            if not pending:
                break
            index, ref = pending[0]
            if choice not in ref.candidates:
                raise BadInputError(f"group {choice + 1} is not one '{ref.phrase}' can mean",
                                    hint="choose one of " + ", ".join(str(c + 1) for c in ref.candidates))
            edit = edit.choose(index, choice)
        return plan_refinement(scene, edit)

    def refine(self, generated: GeneratedScenario, followup: str | Refinement, out_dir: str | Path | None = None, *,
               overwrite: bool = False, choices: Sequence[int] = (), on_event: EventSink | None = None,
               cancel: threading.Event | None = None) -> GeneratedScenario:
        """The scenario edited by a follow-up sentence (or a refinement read before), written as a bundle
        at `out_dir` (the scenario's own folder edits it in place, atomically; without `out_dir`, a new
        folder under `runs_dir`, leaving `generated`'s bundle for the app's undo). Only the groups the
        follow-up adds or changes are generated; the others are kept byte for byte (generation/refine.py)."""
        from grove_tui.files import check_output_dir
        from grove_tui.generation.refine import apply_refinement
        from grove_tui.generation.scene import scene_of
        from grove_tui.scenario.bundle import WHAT, is_bundle
        from grove_tui.services.runs import slug

        stamp = time.strftime("%Y%m%d-%H%M%S")
        refinement = followup if not isinstance(followup, str) else \
            self.read_refinement(generated, followup, choices=choices)
        if out_dir is None:
            out_dir = self.new_run_dir(f"{stamp}-{slug(generated.prompt)}-{generated.seed}-edit{refinement.step}")
        # Before the model runs: a refused or unwritable folder must not cost a generation.
        check_output_dir(out_dir, owned=is_bundle, what=WHAT, overwrite=overwrite)
        scene = scene_of(generated.result, generated.world)
        if refinement.step != scene.steps + 1:
            raise BadInputError("this refinement was read for another version of the scenario; read it again")
        pipeline = self.pipeline(generated.world_name, generated.preset) if refinement.calls_model else \
            self._planning_pipeline(generated)
        result = apply_refinement(pipeline, scene, refinement, on_event=on_event, cancel=cancel)
        bundle = self.write_bundle(result, out_dir, overwrite=overwrite)
        return GeneratedScenario(generated.prompt, generated.world_name, generated.preset, generated.seed,
                                 generated.world, result, bundle)

    def _count_refinement(self, generated: GeneratedScenario, counts: dict[int, int]) -> Refinement:
        """Head counts typed per group (the app's count dialog) as a refinement of their groups."""
        from grove_tui.generation.refine import plan_refinement
        from grove_tui.generation.scene import scene_of
        from grove_tui.language.edits import CountChange, EditReading, GroupEdit, GroupRef

        scene = scene_of(generated.result, generated.world)
        most = self.load_preset(generated.preset).limits.max_count
        edits = []
        for index, count in sorted(counts.items()):
            if not 0 <= index < len(scene.groups):
                raise BadInputError(f"there is no group {index + 1}: this scenario has {len(scene.groups)}")
            if not 1 <= int(count) <= most:
                raise PromptError(f"group '{scene.groups[index].label}': {count} people is out of range; preset "
                                  f"'{generated.preset}' allows 1 to {most} per group")
            label = scene.groups[index].label
            edits.append(GroupEdit("change", f"{label} {count}", GroupRef(label, (index,)), None, ("count",),
                                   CountChange("set", float(count))))
        sentence = "counts: " + ", ".join(e.text for e in edits)
        return plan_refinement(scene, EditReading(sentence, tuple(edits)))

    def _planning_pipeline(self, generated: GeneratedScenario) -> GenerationPipeline:
        """A pipeline for post-processing and planning only (no model loads): count, pace and robot edits."""
        from grove_tui.generation.pipeline import GenerationPipeline

        key = (generated.world_name, generated.preset, "planning-only")
        with self._lock:
            pipeline = self._pipelines.get(key)
        if pipeline is None:
            pipeline = GenerationPipeline(generated.world, self.load_preset(generated.preset), None, None, None)
            with self._lock:
                pipeline = self._pipelines.setdefault(key, pipeline)
        return pipeline

    # simulation -----------------------------------------------------------------------------------------
    def live_metrics(self, generated: GeneratedScenario) -> LiveMetrics:
        """metrics.json's numbers for a run while it runs (analysis.live_metrics.LiveMetrics): fed the
        recorder's new rows, rounded as trajectories.csv stores them, through the accumulators
        `grove metrics` streams the file through, so the app's counters equal the exported metrics.json."""
        from grove_tui.analysis.live_metrics import LiveMetrics

        return LiveMetrics(generated.scenario, generated.world)

    def outcome_checker(self, generated: GeneratedScenario) -> OutcomeChecker | None:
        """A checker of the scenario's planned grounding report for a run as it plays (None without a
        report); feed it with `check_run_rows` from one thread at a time."""
        from grove_tui.analysis.outcomes import OutcomeChecker, planned_report

        planned = planned_report(generated.result.report)
        if planned is None:
            return None
        return OutcomeChecker(planned, generated.scenario, generated.world)

    def check_run_rows(self, checker: OutcomeChecker, rows: np.ndarray, events: Sequence[SimEvent],
                       partial: bool = True) -> GroundingReport:
        """The report checked on the run so far: the recorder's new rows (whole frames, taken between
        steps) go into the checker, rounded as trajectories.csv stores them, so the live report equals
        the grounding.json the same run writes."""
        import numpy as np

        from grove_tui.crowd.recording import CSV_COLUMNS

        if len(rows):
            table = np.column_stack([np.asarray(rows[name], dtype=np.float64) for name in CSV_COLUMNS])
            table[:, 1] = np.round(table[:, 1], 4)
            table[:, 3:8] = np.round(table[:, 3:8], 4)
            checker.add_rows(table)
        return checker.result(events, partial=partial)

    def simulation(self, generated: GeneratedScenario) -> Simulation:
        """A runnable simulation of a generated scenario, for a front end that steps it itself."""
        from grove_tui.simulation.simulation import Simulation

        return Simulation.from_scenario(generated.scenario, generated.bundle_dir, world=generated.world,
                                        params=pedestrian_params())

    def simulate(self, bundle: str | Path, seconds: float | None = None, *, cancel: threading.Event | None = None,
                 runtime_planning: bool = True, model: str | None = None) -> SimulationSummary:
        """Run a bundle's scenario for `seconds`; give it trajectories.csv, events.jsonl and metrics.json.

        `seconds` None: the scenario's own length (generation/run_length.py), long enough for its planned
        behaviours (`scenario_run_seconds`).

        `model`: the pedestrian model ("grove" or "lightsfm"); default the settings' simulation.pedestrian_model.

        The three files replace the old ones in one atomic step: interrupted, the bundle keeps its old run.
        """
        from grove_tui.analysis.bundle_metrics import bundle_metrics
        from grove_tui.scenario.bundle import load_bundle, replace_run_outputs, world_source
        from grove_tui.scenario.events import write_events
        from grove_tui.simulation.simulation import Simulation

        bundle = Path(bundle)
        scenario, _, _, _ = load_bundle(bundle)
        if seconds is None:
            seconds = self.scenario_run_seconds(bundle)
        world = self.load_world(str(world_source(bundle, scenario)))
        sim = Simulation.from_scenario(scenario, bundle, world=world, runtime_planning=runtime_planning,
                                       params=pedestrian_params(model))
        started = time.perf_counter()
        frame = sim.run(seconds, cancel=cancel)
        wall = time.perf_counter() - started
        recorder = sim.recorder
        if recorder is None:
            raise RuntimeFailure(f"{bundle}: the simulation has no trajectory recorder")
        reports = []

        def write_run(stage: Path) -> None:
            recorder.write_csv(stage / "trajectories.csv")
            write_events(stage / "events.jsonl", sim.events)
            # metrics.json and grounding.json (the sentence's claims checked on this run) in one pass
            reports.append(bundle_metrics(stage, outcomes=True)[0])

        replace_run_outputs(bundle, write_run)
        crowd = reports[0].crowd
        counters = asdict(frame.counters) if is_dataclass(frame.counters) else {"value": str(frame.counters)}
        return SimulationSummary(round(float(frame.t), 3), round(wall, 3), counters,
                                 int(crowd.get("wall_penetrations", 0)), crowd.get("goal_reach_rate"))

    def scenario_run_seconds(self, bundle: str | Path) -> float:
        """How long the bundle's scenario runs when the user leaves it to the scenario: the length its
        planned report carries (RUN_FLOOR for a bundle without one: imported, or made before lengths)."""
        from grove_tui.generation.run_length import RUN_FLOOR, scenario_seconds
        from grove_tui.scenario.bundle import REPORT_FILE, load_report

        generation = load_report(Path(bundle)) if (Path(bundle) / REPORT_FILE).is_file() else {}
        return scenario_seconds(generation) or RUN_FLOOR

    def metrics(self, bundle: str | Path) -> BundleMetrics:
        """A simulated bundle's robot and crowd metrics and its grounding report checked on the run, written
        as metrics.json and grounding.json (`grove metrics`)."""
        from grove_tui.analysis.bundle_metrics import bundle_metrics
        from grove_tui.analysis.outcomes import GROUNDING_FILE

        report, path = bundle_metrics(Path(bundle), outcomes=True)
        grounding = Path(bundle) / GROUNDING_FILE
        if not grounding.is_file():  # a bundle without a planned report (generated before it, or imported)
            return BundleMetrics(report, Path(path))
        return BundleMetrics(report, Path(path), json.loads(grounding.read_text(encoding="utf-8")), grounding)

    def picture(self, bundle: str | Path, out: str | Path | None = None, *, trajectories: bool = True,
                width: int = 80, overwrite: bool = False) -> Path | Text:
        """A picture of a bundle's scenario (map, zones, spawns, goals, waypoints, fields, and the run's
        trajectories when it has them and `trajectories`): a PNG, SVG or PDF at `out` (its path), or
        without `out` a drawing `width` columns wide for the terminal."""
        from grove_tui.exports.pictures import draw_scenario, render_scenario_text
        from grove_tui.scenario.bundle import load_bundle_world, load_scenario

        bundle = Path(bundle)
        scenario = load_scenario(bundle)
        world = load_bundle_world(bundle, scenario)
        if out is None:
            return render_scenario_text(world, scenario, width)
        csv = bundle / "trajectories.csv"
        return draw_scenario(world, scenario, bundle, out, trajectories=csv if trajectories and csv.exists() else None,
                             overwrite=overwrite)

    # behavior trees -----------------------------------------------------------------------------------------
    def node_manifest(self, preset: str | None = None) -> list[NodeSpec]:
        """Every behavior-tree node GROVE knows, or only those the model may use under `preset`."""
        from grove_tui.bt.format.manifest import NODES, nodes_for_preset

        return nodes_for_preset(preset) if preset else list(NODES.values())

    def node_manifest_xml(self) -> str:
        """Every node as a Groot2 / BehaviorTree.CPP v4 TreeNodesModel document."""
        from grove_tui.bt.format.manifest import treenodes_model_xml

        return treenodes_model_xml()

    def check_tree_file(self, path: str | Path) -> list[BTProblem]:
        """The problems of a behavior-tree XML file against the manifest, each with its line ([] when it
        is fine). A file that cannot be read at all raises BTError, whose hint says what a tree file must be."""
        from grove_tui.bt.format.source import MAX_BYTES, read_file_bytes
        from grove_tui.bt.format.xml import check_tree_bytes
        from grove_tui.errors import BTError

        try:
            data = read_file_bytes(path)
        except BTError as error:
            raise BTError(error.message,
                          hint=f"give readable tree XML files (regular files of at most {MAX_BYTES:,} bytes)") from None
        return check_tree_bytes(path, data)

    # validation of the crowd ------------------------------------------------------------------------------
    def validate_rimea(self, model: str, tests: Sequence[int] = (), *,
                       jupedsim: bool = True) -> tuple[list[tuple[RimeaResult, RimeaResult | None]], str | None]:
        """The RiMEA verification tests (all when `tests` is empty) on the pedestrian `model`: each GROVE
        result with JuPedSim's beside it for the building tests, and JuPedSim's version (None when it is
        not asked for or not installed)."""
        from grove_tui.analysis.rimea import TESTS, jupedsim_version, run_rimea

        unknown = [t for t in tests if t not in TESTS]
        if unknown:
            raise BadInputError(f"RiMEA test {unknown[0]} is not implemented",
                                hint=f"implemented: {', '.join(map(str, TESTS))}")
        version = jupedsim_version() if jupedsim else None
        return run_rimea(model, tuple(tests) or tuple(TESTS), jupedsim=version is not None), version

    def validate_empirical(self, model: str, checks: Sequence[str] = ()) -> list[EmpiricalResult]:
        """The crowd of pedestrian `model` against measured crowds (all checks when `checks` is empty)."""
        from grove_tui.analysis.empirical import CHECKS, run_empirical

        return run_empirical(model, tuple(checks) or tuple(CHECKS))

    # exports ----------------------------------------------------------------------------------------------
    def export(self, kind: str, bundle: str | Path, out: str | Path, **options: Any) -> Any:  # Any: per format (BY_KIND)
        """Write one export format of a bundle (services.exporting.EXPORT_FORMATS); returns that exporter's result."""
        from grove_tui.services.exporting import BY_KIND, EXPORT_FORMATS

        form = BY_KIND.get(kind)
        if form is None or form.write is None:
            raise BadInputError(f"unknown export format {kind!r}; formats: {', '.join(EXPORT_FORMATS)}")
        return form.write(Path(bundle), Path(out), **options)

    def export_all(self, generated: GeneratedScenario, simulation: Simulation | None, root: str | Path, *,
                   on_progress: Callable[[str, int, int], None] | None = None) -> list[ExportedFile]:
        """Every format (`exporters`) into a new folder under `root`, named by time and prompt: a copy of the
        bundle with the run `simulation` made (None before playing), and each format beside it.
        `on_progress(kind, index, total)` comes before each one; a format that fails is listed with why,
        and the others are still written."""
        from grove_tui.errors import describe_error
        from grove_tui.services.exporting import ExportContext
        from grove_tui.services.runs import free_folder, slug

        stamp = time.strftime("%Y%m%d-%H%M%S")
        out_dir = free_folder(Path(root), f"{stamp}-{slug(generated.prompt)}")
        out_dir.mkdir(parents=True)
        ctx = ExportContext(generated, simulation, out_dir, self)
        for index, (kind, exporter) in enumerate(self.exporters):
            if on_progress is not None:
                on_progress(kind, index, len(self.exporters))
            try:
                exporter(ctx)
            except Exception as exc:  # one failing format must not lose the others; the dialog shows why
                if kind == "bundle":
                    raise
                ctx.add(kind, out_dir, f"failed: {describe_error(exc).text}")
        return ctx.files

    # bundles derived from bundles ----------------------------------------------------------------------------
    def write_variant(self, base_bundle: str | Path, target: str | Path, scenario: Scenario,
                      trees: Mapping[str, TreeDocument]) -> Path:
        """A rewrite of a bundle's scenario and trees (an evaluation baseline) as a bundle at `target`: the
        base's grid and report (and its fields, when the rewrite keeps any), the new trees and scenario."""
        from grove_tui.scenario.bundle import GRID_FILE, REPORT_FILE, derive_bundle

        def keep(rel: PurePosixPath) -> bool:
            return str(rel) in (GRID_FILE, REPORT_FILE) or (bool(scenario.fields) and rel.parts[0] == "fields")

        derive_bundle(base_bundle, target, scenario, keep=keep, trees=trees)
        return Path(target)

    def record_episode(self, source: str | Path, out_dir: str | os.PathLike[str], scenario: Scenario,
                       episode: Mapping[str, object],
                       simulation: Simulation, *, overwrite: bool = False) -> Path:
        """A robot policy's episode (gym.recording) as a bundle at `out_dir`: the source bundle's files, the
        scenario with the driven path, `episode` as episode.json, and the run the simulation made."""
        from grove_tui.analysis.bundle_metrics import bundle_metrics
        from grove_tui.scenario.bundle import EPISODE_FILE, derive_bundle
        from grove_tui.scenario.events import write_events

        recorder = simulation.recorder
        if recorder is None:
            raise RuntimeFailure(f"{source}: the episode's simulation has no trajectory recorder")

        def write_run(stage: Path) -> None:
            (stage / EPISODE_FILE).write_text(json.dumps(dict(episode), indent=1) + "\n", encoding="utf-8")
            recorder.write_csv(stage / "trajectories.csv")
            write_events(stage / "events.jsonl", simulation.events)
            bundle_metrics(stage)

        return derive_bundle(source, out_dir, scenario, keep=lambda rel: str(rel) != EPISODE_FILE, write=write_run,
                             overwrite=overwrite)

    def import_hunav(self, agents_yaml: str | Path, out_dir: str | Path, *, world: str | None = None,
                     trees_dir: str | Path | None = None, overwrite: bool = False) -> Path:
        """A HuNavSim scenario (agents YAML and its trees, exports.hunav_import) as a bundle at `out_dir`."""
        from grove_tui.exports.hunav_import import read_hunav

        result = read_hunav(agents_yaml, world=world, trees_dir=trees_dir)
        return self.write_bundle(result, out_dir, overwrite=overwrite)

    # batch ------------------------------------------------------------------------------------------------
    def check_jobs(self, jobs: Sequence[BatchJob], out_dir: Path,
                   overwrite: bool) -> tuple[list[BatchJob], list[JobProblem]]:
        """Jobs whose world, preset and output folder are usable; the others as problems, before any model loads."""
        from grove_tui.files import check_output_dir
        from grove_tui.scenario.bundle import WHAT, is_bundle
        from grove_tui.services.jobs import JobProblem

        check_output_dir(out_dir, owned=lambda _path: True, what="batch folder", overwrite=True)
        good, refused = [], []
        for job in jobs:
            try:
                self.check_request(ScenarioRequest(job.world, job.preset, job.prompt, job.seed))
                check_output_dir(out_dir / job.name, owned=is_bundle, what=WHAT, overwrite=overwrite)
            except GroveError as exc:
                refused.append(JobProblem(job.line, str(exc)))
                continue
            good.append(job)
        return good, refused

    def run_job(self, job: BatchJob, out_dir: Path, *, overwrite: bool = False,
                on_event: EventSink | None = None, cancel: threading.Event | None = None) -> JobOutcome:
        """Generate one job's bundle, simulate it and write its exports. A model error or a
        cancellation stops the whole batch (it is raised); any other error is the job's outcome."""
        target = out_dir / job.name
        try:
            generated = self.generate(ScenarioRequest(job.world, job.preset, job.prompt, job.seed,
                                                      variation=job.variation), target,
                                      overwrite=overwrite, on_event=on_event, cancel=cancel)
            for followup in job.refine:  # each step replaces the job's bundle, atomically
                generated = self.refine(generated, followup, target, overwrite=True, on_event=on_event,
                                        cancel=cancel)
            from grove_tui.services.jobs import SCENARIO_LENGTH

            summary = self.simulate(generated.bundle_dir, None if job.simulate == SCENARIO_LENGTH else job.simulate,
                                    cancel=cancel) if job.simulate else None
            exports = {kind: self._batch_export(kind, generated.bundle_dir, out_dir, job.name, overwrite)
                       for kind in job.exports}
        except GroveError as exc:
            if exc.exit_code in (EXIT_MODEL_ERROR, EXIT_CANCELLED):
                raise
            return JobOutcome(job, target, error=exc)
        return JobOutcome(job, target, generated, summary, exports)

    def _batch_export(self, kind: str, bundle: Path, out_dir: Path, name: str, overwrite: bool) -> Path:
        # Beside the bundle, never inside it: a bundle holds only what generation and simulation wrote.
        # Each export replaces its own earlier output; anything else only with the batch's --overwrite.
        if kind == "foxglove":
            return Path(self.export(kind, bundle, out_dir / f"{name}.mcap", overwrite=overwrite).mcap)
        target = out_dir / f"{name}.{kind}"
        result = self.export(kind, bundle, target, overwrite=overwrite)
        return target if not hasattr(result, "directory") else Path(result.directory)

    def batch(self, jobs: Sequence[BatchJob], out_dir: str | Path, *, overwrite: bool = False,
              events_for: Callable[[int, BatchJob], EventSink | None] | None = None,
              on_outcome: Callable[[int, JobOutcome], None] | None = None,
              cancel: threading.Event | None = None) -> list[JobOutcome]:
        """Run checked jobs in order with the models loaded once; one outcome per job."""
        outcomes = []
        for index, job in enumerate(jobs, start=1):
            sink = events_for(index, job) if events_for is not None else None
            outcome = self.run_job(job, Path(out_dir), overwrite=overwrite, on_event=sink, cancel=cancel)
            outcomes.append(outcome)
            if on_outcome is not None:
                on_outcome(index, outcome)
        return outcomes

    # evaluation -------------------------------------------------------------------------------------------
    def load_eval_suite(self, path: str | Path) -> list[EvalCase]:
        """The cases of an evaluation suite (YAML: world, preset, prompt, seed, what to expect)."""
        from grove_tui.analysis.evaluation import load_suite

        return load_suite(path)

    def evaluation_summary(self, results: Sequence[CaseResult]) -> list[EvaluationRow]:
        """Per (preset, method), sorted: the grounding and plausibility scores and the mean of every column."""
        from grove_tui.analysis.evaluation import grounding_score, plausibility_score, summarize

        return [EvaluationRow(preset, method, grounding_score(row), plausibility_score(row), row)
                for (preset, method), row in sorted(summarize(results).items())]

    def evaluate(self, cases: Sequence[EvalCase], out_dir: str | Path, *, methods: Iterable[str] | None = None,
                 sim_seconds: float = 30.0, command: str = "",
                 on_progress: Callable[[int, int, CaseResult], None] | None = None) -> list[CaseResult]:
        """Generate, simulate and score every case with every method; bundles are kept under out_dir, with
        results.csv and RESULTS.md (`command`: how the run was asked for, recorded in RESULTS.md).

        `grove` and `vanilla` generate through `generate` (so their bundles are those of `grove generate`
        for the same request); `no-planner` and `decoupled` rewrite GROVE's bundle (analysis.evaluation).
        """
        from grove_tui.analysis.evaluation import (
            METHODS,
            CaseResult,
            baseline_variant,
            score_scenario,
            write_results,
        )
        from grove_tui.analysis.metrics import Trajectories
        from grove_tui.scenario.events import read_events

        chosen = list(METHODS if methods is None else methods)
        unknown = [m for m in chosen if m not in METHODS]
        if unknown:
            raise EvalError(f"unknown method(s) {unknown}; choose from {', '.join(METHODS)}")
        out = Path(out_dir)
        results: list[CaseResult] = []
        for index, case in enumerate(cases, start=1):
            world = self.load_world(case.world)
            generated: dict[str, tuple[Scenario, TreeFiles, Path]] = {}

            def generate_method(method: str) -> tuple[Scenario, TreeFiles, Path]:
                preset = case.preset if method == "grove" else "vanilla"
                made = self.generate(ScenarioRequest(case.world, preset, case.prompt, case.seed),
                                     out / "bundles" / case.id / method)
                return made.scenario, made.result.trees, made.bundle_dir  # the documents it wrote, not read back

            for method in chosen:
                started = time.perf_counter()
                try:
                    if method in ("grove", "vanilla"):
                        generated[method] = generate_method(method)
                    else:
                        if "grove" not in generated:
                            generated["grove"] = generate_method("grove")
                        grove_scenario, grove_trees, grove_bundle = generated["grove"]
                        variant, variant_trees = baseline_variant(method, world, grove_scenario, grove_trees)
                        generated[method] = (variant, variant_trees,
                                             self.write_variant(grove_bundle, out / "bundles" / case.id / method,
                                                                variant, variant_trees))
                    scenario, trees, bundle = generated[method]
                    self.simulate(bundle, sim_seconds, runtime_planning=method != "no-planner")
                    traj = Trajectories.from_csv(bundle / "trajectories.csv")
                    events = read_events(bundle / "events.jsonl")
                    report_path = bundle / "generation.json"
                    report = json.loads(report_path.read_text(encoding="utf-8")) if report_path.exists() else {}
                    checked_path = bundle / "grounding.json"
                    if checked_path.is_file():  # the report checked on this run: its ✓ is earned there
                        report = dict(report, grounding=json.loads(checked_path.read_text(encoding="utf-8")))
                    by_id = {a.id: trees[a.tree] for a in scenario.agents}
                    scored = score_scenario(case, method, world, scenario, by_id, traj, events,
                                            report if method in ("grove", "vanilla") else None)
                except GroveError as exc:
                    # A broken model or a cancellation stops the evaluation; a prompt too long for the
                    # model's context (vanilla's whole-world prompt on a small model) fails only its case.
                    if exc.exit_code in (EXIT_MODEL_ERROR, EXIT_CANCELLED) and not isinstance(exc, ContextTooSmallError):
                        raise
                    scored = CaseResult(case=case, method=method, error=str(exc))
                scored.scores["eval_seconds"] = round(time.perf_counter() - started, 3)
                results.append(scored)
                if on_progress is not None:
                    on_progress(index, len(cases), scored)
        write_results(results, out, command=command)
        return results


    def load_understanding_cases(self, path: str | Path) -> list[UnderstandingCase]:
        """The labelled prompts of an understanding suite (what each sentence asks, field by field)."""
        from grove_tui.analysis.understanding import load_cases

        return load_cases(path)

    def read_cases(self, cases: Sequence[UnderstandingCase]) -> list[ReadingScore]:
        """Every case's prompt read by the reader (no model) and scored field by field."""
        from grove_tui.analysis.understanding import run_reading

        return run_reading(cases)

    def understanding_sample(self, cases: Sequence[UnderstandingCase], count: int) -> list[UnderstandingCase]:
        """`count` cases spread over the suite's classes and worlds, to generate and score with the model."""
        from grove_tui.analysis.understanding import sample_cases

        return sample_cases(cases, count)

    def understanding_report(self, reading: Sequence[ReadingScore], scenarios: Sequence[ScenarioScore],
                             out_dir: str | Path, command: str = "") -> UnderstandingReport:
        """The results of an understanding run written under `out_dir`, and their summary tables."""
        from grove_tui.analysis.understanding import (
            below_threshold,
            summarize_reading,
            summarize_scenarios,
            write_results,
        )

        paths = write_results(reading, scenarios, out_dir, command=command)
        by_field = summarize_reading(reading)
        return UnderstandingReport(paths, by_field, summarize_scenarios(scenarios) if scenarios else {},
                                   below_threshold(by_field))

    def understand(self, cases: Sequence[UnderstandingCase], out_dir: str | Path, *,
                   on_progress: Callable[[int, int, ScenarioScore], None] | None = None) -> list[ScenarioScore]:
        """Generate each understanding case through `generate` and score its scenario; bundles are kept
        under out_dir/bundles. A case that fails is scored as failed on every field."""
        from grove_tui.analysis.understanding import SCENARIO_FIELDS, ScenarioScore, score_scenario
        from grove_tui.bt.format.manifest import NODES

        action_names = frozenset(name for name, spec in NODES.items() if spec.category == "action")
        scores: list[ScenarioScore] = []
        for index, case in enumerate(cases, start=1):
            started = time.perf_counter()
            try:
                made = self.generate(ScenarioRequest(case.world, case.preset, case.prompt, case.seed),
                                     Path(out_dir) / "bundles" / case.id)
                score = score_scenario(case, made.world, made.scenario, made.result.trees, action_names)
            except GroveError as exc:
                if exc.exit_code in (EXIT_MODEL_ERROR, EXIT_CANCELLED):
                    raise  # a broken model or a cancellation stops the run, not one case
                score = ScenarioScore(case, error=str(exc))
                for name in SCENARIO_FIELDS:
                    score.set(name, False, score.error)
            score.seconds = time.perf_counter() - started
            scores.append(score)
            if on_progress is not None:
                on_progress(index, len(cases), score)
        return scores


def _close(llm: object) -> None:
    closer = getattr(llm, "close", None)
    if callable(closer):
        closer()


def _is_running(llm: object) -> bool:
    if llm is None:
        return False
    running = getattr(llm, "running", None)
    return True if running is None else bool(running)


def pedestrian_params(model: str | None = None) -> SFMParams:
    """SFMParams of a pedestrian model by name, or of the settings' simulation.pedestrian_model."""
    from grove_tui.crowd.sfm import SFMParams
    from grove_tui.settings import PEDESTRIAN_MODELS, load_settings

    name = model if model is not None else load_settings().simulation.pedestrian_model
    if name not in PEDESTRIAN_MODELS:
        raise BadInputError(f"unknown pedestrian model {name!r}", hint=f"choose one of {', '.join(PEDESTRIAN_MODELS)}")
    return SFMParams.named(name)
