"""The app's seam over the application layer (`services.session.GroveSession`).

Screens call only this module, from worker threads. It adds what only the app needs: run folders
named by time and prompt, and the export dialog's list of formats; everything else (worlds,
presets, models, generation, re-planning, simulation, exports) is the session's, as for the CLI.
Tests pass an `llm_factory` that returns a fake model (UI-only tests) or use the real embedded model.
"""

from __future__ import annotations

import os
import re
import shutil
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from grove_tui.errors import GenerationError, GroveError, PromptError, describe_error
from grove_tui.services.session import (
    GeneratedScenario,
    GroveSession,
    LLMFactory,
    ModelStatus,
    RetrieverFactory,
    ScenarioRequest,
    WarmUpStatus,
)
from grove_tui.settings import data_dir

# How far below the app's priority the model processes run while the app is open (see
# EngineBackend.yield_cpu_to_the_app); 0 leaves them alone.
MODEL_NICENESS = 10
LOWEST_PRIORITY = 19  # the largest niceness POSIX allows

__all__ = ["EXPORTERS", "EngineBackend", "ExportContext", "ExportedFile", "GeneratedScenario", "ModelStatus",
           "PresetInfo", "RunInfo", "WarmUpStatus", "list_runs"]


@dataclass(frozen=True)
class PresetInfo:
    name: str
    description: str


@dataclass(frozen=True)
class RunInfo:
    """One saved bundle in the runs folder, as the recent-runs list shows it."""

    path: Path
    modified: float  # seconds since the epoch, of scenario.yaml
    prompt: str = ""
    world: str = ""
    preset: str = ""
    seed: int = 0
    agents: int = 0
    simulated: bool = False
    error: str = ""  # why the bundle cannot be opened; empty when it can


def list_runs(runs_dir: Path, limit: int = 50) -> list[RunInfo]:
    """The newest `limit` bundles directly under `runs_dir` (a missing folder is an empty list)."""
    from grove_tui.scenario.bundle import SCENARIO_FILE, is_bundle
    from grove_tui.scenario.model import Scenario

    if not runs_dir.is_dir():
        return []
    bundles = [path for path in runs_dir.iterdir() if path.is_dir() and is_bundle(path)]
    bundles.sort(key=lambda path: (path / SCENARIO_FILE).stat().st_mtime, reverse=True)
    runs = []
    for path in bundles[:limit]:
        modified = (path / SCENARIO_FILE).stat().st_mtime
        try:
            scenario = Scenario.load(path / SCENARIO_FILE)
        except (GroveError, OSError) as exc:  # a broken scenario.yaml, or a file that vanished meanwhile
            runs.append(RunInfo(path, modified, error=str(exc)))
            continue
        runs.append(RunInfo(path, modified, scenario.prompt, scenario.world, scenario.preset, int(scenario.seed),
                            len(scenario.agents), (path / "trajectories.csv").is_file()))
    return runs


@dataclass(frozen=True)
class ExportedFile:
    kind: str
    path: Path
    note: str = ""  # why it is missing, when an exporter could not write it


@dataclass
class ExportContext:
    generated: GeneratedScenario
    simulation: Any | None  # a Simulation that has run (trajectories, events), or None before simulating
    out_dir: Path
    session: GroveSession = field(default_factory=GroveSession)
    files: list[ExportedFile] = field(default_factory=list)

    @property
    def bundle(self) -> Path:
        return self.out_dir / "bundle"

    @property
    def trajectories(self) -> Path:
        return self.bundle / "trajectories.csv"

    def add(self, kind: str, path: Path, note: str = "") -> None:
        self.files.append(ExportedFile(kind, path, note))


Exporter = Callable[[ExportContext], None]


def export_bundle(ctx: ExportContext) -> None:
    shutil.copytree(ctx.generated.bundle_dir, ctx.bundle)
    ctx.add("bundle", ctx.bundle)


def export_run(ctx: ExportContext) -> None:
    """Trajectories and the event log go into the exported bundle, so `grove metrics` reads it as is."""
    if ctx.simulation is None:
        return
    from grove_tui.scenario.events import write_events

    recorder = getattr(ctx.simulation, "recorder", None)
    if recorder is None:
        ctx.add("trajectories", ctx.trajectories, "not recorded: this simulation has no trajectory recorder")
    else:
        recorder.write_csv(ctx.trajectories)
        ctx.add("trajectories", ctx.trajectories)
    events = write_events(ctx.bundle / "events.jsonl", ctx.simulation.events)
    ctx.add("events", Path(events))


def export_metrics(ctx: ExportContext) -> None:
    if ctx.simulation is None or not ctx.trajectories.exists():
        return
    from grove_tui.analysis.bundle_metrics import bundle_metrics

    _report, path = bundle_metrics(ctx.bundle)
    ctx.add("metrics", Path(path))


def export_hunav_files(ctx: ExportContext) -> None:
    result = ctx.session.export("hunav", ctx.bundle, ctx.out_dir / "hunav")
    ctx.add("hunav", Path(result.agents_yaml), f"+ {len(result.trees)} agent trees")


def export_picture(ctx: ExportContext) -> None:
    from grove_tui.exports.pictures import draw_scenario

    trajectories = ctx.trajectories if ctx.trajectories.exists() else None
    path = draw_scenario(ctx.generated.world, ctx.generated.scenario, ctx.bundle, ctx.out_dir / "scenario.png",
                         trajectories=trajectories, title=ctx.generated.prompt[:80])
    ctx.add("picture", Path(path))


def export_rosbag_files(ctx: ExportContext) -> None:
    """A ROS 2 bag of the run; a note instead when the `ros` extra is missing."""
    if ctx.simulation is None or not ctx.trajectories.exists():
        return
    from grove_tui.exports.rosbag import missing_dependency

    out = ctx.out_dir / "rosbag"
    missing = missing_dependency()
    if missing is not None:
        ctx.add("rosbag", out, f"not written: {missing}")
        return
    result = ctx.session.export("rosbag", ctx.bundle, out)
    ctx.add("rosbag", result.directory, f"{result.frames} frames")


def export_foxglove_files(ctx: ExportContext) -> None:
    """A Foxglove MCAP of the run and its layout; a note instead when the `ros` extra is missing."""
    if ctx.simulation is None or not ctx.trajectories.exists():
        return
    from grove_tui.exports.foxglove import missing_dependency

    out = ctx.out_dir / "scenario.mcap"
    missing = missing_dependency()
    if missing is not None:
        ctx.add("foxglove", out, f"not written: {missing}")
        return
    result = ctx.session.export("foxglove", ctx.bundle, out)
    ctx.add("foxglove", result.mcap, f"+ layout {result.layout.name}")


# Order matters: later exporters read what earlier ones wrote into the exported bundle.
EXPORTERS: list[tuple[str, Exporter]] = [
    ("bundle", export_bundle),
    ("trajectories", export_run),
    ("metrics", export_metrics),
    ("hunav", export_hunav_files),
    ("picture", export_picture),
    ("rosbag", export_rosbag_files),
    ("foxglove", export_foxglove_files),
]


STEP_SECONDS_FILE = "warm_up_seconds.json"


def load_step_seconds() -> dict[str, float]:
    """Seconds each warm-up step took last time on this machine (data dir); {} before the first warm-up."""
    import json

    try:
        data = json.loads((data_dir() / STEP_SECONDS_FILE).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    if not isinstance(data, dict):
        return {}
    return {str(k): float(v) for k, v in data.items() if isinstance(v, (int, float)) and 0 <= v < 3600}


def save_step_seconds(seconds: dict[str, float]) -> None:
    import json

    from grove_tui.files import write_text_atomic

    if not seconds:
        return
    path = data_dir() / STEP_SECONDS_FILE
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        write_text_atomic(path, json.dumps(dict(sorted(seconds.items())), indent=2) + "\n")
    except OSError:
        pass  # an ETA is a nicety: a read-only data dir must not fail a generation


def _slug(text: str, limit: int = 40) -> str:
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-")[:limit] or "scenario"


class EngineBackend:
    """Worlds, presets, models, generation, simulation and export, for the app's workers."""

    def __init__(
        self,
        model: str | None = None,
        roi_model: str | None = None,
        bt_model: str | None = None,
        llm_factory: LLMFactory | None = None,
        retriever_factory: RetrieverFactory | None = None,
        runs_dir: Path | None = None,
        exporters: list[tuple[str, Exporter]] | None = None,
        model_niceness: int = MODEL_NICENESS,
    ) -> None:
        self.model_niceness = model_niceness
        self.session = GroveSession(model=model, roi_model=roi_model, bt_model=bt_model, llm_factory=llm_factory,
                                    retriever_factory=retriever_factory)
        self.runs_dir = runs_dir if runs_dir is not None else data_dir() / "runs"
        self.exporters = list(EXPORTERS if exporters is None else exporters)
        # What each warm-up step took on this machine last time: the ETA of the loading the app shows.
        self.session.step_seconds.update(load_step_seconds())
        self._retriever_factory = retriever_factory
        self._embedder_warm = False

    # worlds and presets ------------------------------------------------------------------------------
    def list_worlds(self) -> list[str]:
        return self.session.list_worlds()

    def load_world(self, name: str) -> Any:
        return self.session.load_world(name)

    def presets(self) -> list[PresetInfo]:
        from grove_tui.generation.presets import list_presets

        infos = []
        for name in list_presets():
            try:
                infos.append(PresetInfo(name, self.session.load_preset(name).description))
            except GroveError as exc:
                infos.append(PresetInfo(name, f"(broken: {exc})"))
        return infos

    # models --------------------------------------------------------------------------------------
    def model_status(self) -> list[ModelStatus]:
        return self.session.model_status()

    def load_models(self) -> dict[str, Any]:
        """Load each role's model once (roles sharing a file share the instance)."""
        models = self.session.load_models()
        return {"roi": models.roi, "bt": models.bt}

    def warm_up(self, world: str | None = None, preset: str | None = None, *,
                on_status: Callable[[WarmUpStatus], None] | None = None) -> list[WarmUpStatus]:
        """GroveSession.warm_up (models, node index and embedder, reader, the world's planner); each
        step's WarmUpStatus goes to `on_status`, whose `text` is the app's status line."""
        def relay(status: WarmUpStatus) -> None:
            if status.step == "retrieval" and status.state == "done":
                self._embedder_warm = True
            if on_status is not None:
                on_status(status)

        try:
            return self.session.warm_up(world, preset, on_status=relay)
        finally:
            save_step_seconds(self.session.step_seconds)

    def yield_cpu_to_the_app(self) -> list[int]:
        """Run the model processes `model_niceness` steps below the app's priority; the pids changed.

        llama.cpp sizes its threads to the cores free when its process starts and spins at its
        barriers, so while it writes it holds every core and the app's key handling waits for a time
        slice (0.4-0.8 s per key in issue 21). One step of niceness is ~1.25x less CPU weight, so at +10
        the app's thread takes a core within the scheduler's latency whenever it has work, and the
        model loses only the little CPU the app uses. Niceness cannot be lowered again without
        privileges, so this is only done for the app's own model processes, and is idempotent.
        """
        if self.model_niceness <= 0 or not hasattr(os, "setpriority"):
            return []
        target = min(os.getpriority(os.PRIO_PROCESS, 0) + self.model_niceness, LOWEST_PRIORITY)
        changed = []
        for llm in self.session.loaded_models():
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

    def warm_up_retriever(self) -> None:
        """Open the node index and load the embedding model now, so the first Retrieval takes no extra time."""
        self.session.warm_up_retrieval()
        self._embedder_warm = True

    def embedder_ready(self) -> bool:
        """Whether retrieval runs without first loading the embedding model (warmed, or used once)."""
        return self._embedder_warm or self._retriever_factory is not None

    def close(self) -> None:
        self.session.close()

    # generation ------------------------------------------------------------------------------------
    def unsure(self, world_name: str, preset_name: str, prompt: str, seed: int) -> list[str]:
        """Questions about the fields the reader is unsure of in the sentence (asked before generating)."""
        return self.session.unsure(ScenarioRequest(world_name, preset_name, prompt, seed))

    def generate(
        self,
        world_name: str,
        preset_name: str,
        prompt: str,
        seed: int,
        on_event: Callable[[Any], None] | None = None,
        cancel: threading.Event | None = None,
    ) -> GeneratedScenario:
        stamp = time.strftime("%Y%m%d-%H%M%S")
        request = ScenarioRequest(world_name, preset_name, prompt, seed)
        try:
            # The app shows a stage "loading" for what its warm-up has not loaded yet (with an ETA), so
            # a generation asked early is never silent; the command line loads as it goes.
            self.session.check_request(request)
            self.session.prepare(world_name, preset_name, on_event=on_event, cancel=cancel)
            generated = self.session.generate(request, self._free_run_dir(f"{stamp}-{_slug(prompt)}-{seed}"),
                                              on_event=on_event, cancel=cancel)
        finally:
            save_step_seconds(self.session.step_seconds)
        self._embedder_warm = True  # retrieval ran: the embedding model is loaded for the next run
        return generated

    def replan(
        self,
        generated: GeneratedScenario,
        counts: dict[int, int],
        seed: int | None = None,
        on_event: Callable[[Any], None] | None = None,
        cancel: threading.Event | None = None,
    ) -> GeneratedScenario:
        """The same draft with new head counts (group index -> count), re-planned without the model.

        The new scenario gets its own bundle next to the first one; `generated` is left as it was.
        """
        stamp = time.strftime("%Y%m%d-%H%M%S")
        out = self._free_run_dir(f"{stamp}-{_slug(generated.prompt)}-{generated.seed if seed is None else seed}-counts")
        try:
            return self.session.replan(generated, counts, out, seed=seed, on_event=on_event, cancel=cancel)
        except PromptError as exc:
            # The counts, not the prompt, are what the user changed here: say what to do with them.
            exc.hint = "Lower the counts of the groups in that zone, or regenerate with a roomier place."
            raise
        except GenerationError as exc:
            exc.hint = "Change the counts and press Enter again, or Escape to keep the scenario as it is."
            raise

    def read_refinement(self, generated: GeneratedScenario, sentence: str, choices: tuple[int, ...] = ()) -> Any:
        """What a follow-up would change, as a diff (no model; AmbiguousEditError asks which group)."""
        return self.session.read_refinement(generated, sentence, choices=choices)

    def refine(self, generated: GeneratedScenario, refinement: Any, on_event: Callable[[Any], None] | None = None,
               cancel: threading.Event | None = None) -> GeneratedScenario:
        """The scenario edited by a refinement read before, in its own bundle next to the first one;
        `generated` and its bundle are left as they were (the app's undo goes back to them)."""
        stamp = time.strftime("%Y%m%d-%H%M%S")
        out = self._free_run_dir(f"{stamp}-{_slug(generated.prompt)}-{generated.seed}-edit{refinement.step}")
        return self.session.refine(generated, refinement, out, on_event=on_event, cancel=cancel)

    def _free_run_dir(self, name: str) -> Path:
        out, suffix = self.runs_dir / name, 1
        while out.exists():
            suffix += 1
            out = self.runs_dir / f"{name}-{suffix}"
        return out

    # simulation ------------------------------------------------------------------------------------
    def simulation(self, generated: GeneratedScenario) -> Any:
        return self.session.simulation(generated)

    def live_metrics(self, generated: GeneratedScenario) -> Any:
        """metrics.json's numbers for a run while it runs (analysis.live_metrics.LiveMetrics): fed the
        recorder's new rows, rounded as trajectories.csv stores them, through the accumulators
        `grove metrics` streams the file through, so the app's counters equal the exported metrics.json."""
        from grove_tui.analysis.live_metrics import LiveMetrics

        return LiveMetrics(generated.scenario, generated.world)

    def outcome_checker(self, generated: GeneratedScenario) -> Any:
        """A checker of the scenario's planned grounding report for a run as it plays (None without a
        report); feed it with `check_run_rows` from one thread at a time."""
        from grove_tui.analysis.outcomes import OutcomeChecker, planned_report

        planned = planned_report(generated.result.report)
        if planned is None:
            return None
        return OutcomeChecker(planned, generated.scenario, generated.world)

    def check_run_rows(self, checker: Any, rows: Any, events: list[Any], partial: bool = True) -> Any:
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

    # export ----------------------------------------------------------------------------------------
    def export(self, generated: GeneratedScenario, simulation: Any | None, root: Path,
               on_progress: Callable[[str, int, int], None] | None = None) -> list[ExportedFile]:
        """Every format into a new folder under `root`; `on_progress(kind, index, total)` before each one."""
        stamp = time.strftime("%Y%m%d-%H%M%S")
        out_dir = Path(root) / f"{stamp}-{_slug(generated.prompt)}"
        suffix = 1
        while out_dir.exists():
            suffix += 1
            out_dir = Path(root) / f"{stamp}-{_slug(generated.prompt)}-{suffix}"
        out_dir.mkdir(parents=True)
        ctx = ExportContext(generated, simulation, out_dir, self.session)
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


    # saved runs --------------------------------------------------------------------------------------
    def recent_runs(self, limit: int = 50) -> list[RunInfo]:
        """Bundles under the runs folder, newest first; a broken one is listed with what is wrong."""
        return list_runs(self.runs_dir, limit)

    def open_run(self, bundle_dir: Path) -> GeneratedScenario:
        """A saved bundle as the app holds a fresh generation (no draft: counts cannot be re-planned)."""
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
