"""Messages the app's worker threads post back to the UI (post_message is thread-safe)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from textual.message import Message

if TYPE_CHECKING:
    from grove_tui.scenario.report import GroundingReport
    from grove_tui.services.domain import Simulation, World
    from grove_tui.services.exporting import ExportedFile
    from grove_tui.services.session import GeneratedScenario, ModelStatus, PresetInfo
    from grove_tui.tui.screens.generation import GenerationRequest


@dataclass
class WorldsListed(Message):
    names: list[str]
    error: str = ""


@dataclass
class WorldLoaded(Message):
    name: str
    world: World


@dataclass
class WorldFailed(Message):
    name: str
    error: str


@dataclass
class PresetsListed(Message):
    presets: list[PresetInfo]


@dataclass
class ModelsChanged(Message):
    statuses: list[ModelStatus]
    loading: bool = False
    embedder: str = ""  # the node retriever's embedding model: "", "loading", "ready" or its error
    warm_up: str = ""  # the session's warm-up status line ("loading the models…"), "" when none runs
    expected_seconds: float = 0.0  # a running step: how long it took last time (the line counts down from it)


@dataclass
class StageStarted(Message):
    stage: str


@dataclass
class StageFinished(Message):
    stage: str
    seconds: float
    prompt_tokens: int
    completion_tokens: int
    detail: str


@dataclass
class TokensFlushed(Message):
    """The streamed model text of a stage so far; a newer flush replaces one still queued."""

    stage: str
    text: str
    tokens: int = 0  # tokens streamed in this attempt so far (each TokenStreamed is one token)
    attempt: int = 1  # the stage's model call the text belongs to

    def can_replace(self, message: Message) -> bool:
        return isinstance(message, TokensFlushed) and (message.stage, message.attempt) == (self.stage, self.attempt)


@dataclass
class LoadingPartStarted(Message):
    """The stage "loading" starts part `index` of `parts` (services.session.LoadingProgress)."""

    doing: str
    index: int
    parts: int
    expected_seconds: float
    later_seconds: float


@dataclass
class AttemptStarted(Message):
    """The stage asks the model again (`attempt` 2 is the first retry); the text streamed before is discarded."""

    stage: str
    attempt: int
    reason: str


@dataclass
class GenerationSucceeded(Message):
    generated: GeneratedScenario
    note: str = ""  # what happened to count edits carried over from the previous scenario


@dataclass
class GenerationFailed(Message):
    stage: str
    error: str
    hint: str


@dataclass
class GenerationStopped(Message):
    """The user cancelled the generation (the engine raised grove_tui.errors.Cancelled or stopped early)."""

    stage: str


@dataclass
class SimulationReady(Message):
    simulation: Simulation


@dataclass
class SimulationFailed(Message):
    error: str


@dataclass
class ExportFinished(Message):
    files: list[ExportedFile]
    out_dir: Path


@dataclass
class ExportFailed(Message):
    error: str


@dataclass
class RunOpened(Message):
    generated: GeneratedScenario  # loaded from a saved bundle


@dataclass
class RunOpenFailed(Message):
    bundle_dir: Path
    error: str


@dataclass
class RunEnded(Message):
    """The run is over at simulated time `t`: every one of its `agents` is out of the building (`out`)
    or done with their tree, and the simulation paused itself. `text` says it ("all 40 out at t = 83 s");
    the run's files (trajectories, events, metrics) are complete up to `t`."""

    t: float
    text: str
    agents: int
    out: int


@dataclass
class ExportProgress(Message):
    """The exporter `kind` (number `index` of `total`) starts."""

    kind: str
    index: int
    total: int


@dataclass
class ReadingChecked(Message):
    """The sentence was read before generating: the questions about what the reader is unsure of."""

    request: GenerationRequest
    questions: list[str]


@dataclass
class GroundingChecked(Message):
    """The sentence's claims checked on the run so far (analysis/outcomes.py), or why they could not be."""

    report: GroundingReport | None  # None on error
    error: str = ""
    final: bool = False  # checked on the whole run, once it ended
