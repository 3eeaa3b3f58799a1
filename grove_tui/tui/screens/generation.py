"""Generation view: pipeline stages with timings and tokens, the model's streamed output, cancel, errors."""

from __future__ import annotations

import sys
import threading
import time
from textwrap import shorten
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from textual import work
from textual.app import ComposeResult
from textual.binding import Binding
from textual.message import Message
from textual.screen import Screen
from rich.segment import Segment
from textual.strip import Strip
from textual.widgets import DataTable, Static
from textual.worker import get_current_worker

from grove_tui.errors import describe_error
from grove_tui.services.session import (AttemptStarted, Event, LoadingProgress, ScenarioRequest, StageFinished, StageStarted,
                                        TokenStreamed)
from grove_tui.tui import messages as msg
from grove_tui.tui.widgets.footer import Footer

if TYPE_CHECKING:
    from grove_tui.jsontypes import Parsed
    from grove_tui.tui.app import GroveApp
    from grove_tui.tui.commands import CommandEntry
    from grove_tui.tui.screens.inspect import InspectScreen

STAGES = {
    "loading": "Loading",
    "rois": "RoIs",
    "retrieval": "Retrieval",
    "synthesis": "Tree synthesis",
    "postprocess": "Post-processing",
    "planning": "Planning",
}
STREAM_TAIL_CHARS = 1600
ATTEMPT_REASON_CHARS = 160  # a draft error can be long; the header of a retry keeps to a line or two
FLUSH_SECONDS = 0.05  # ~20 Hz: smooth enough to read, cheap for the UI thread
UI_SWITCH_INTERVAL = 0.001  # seconds; Python's default 0.005 lets a busy worker hold the GIL 5x longer
PROGRESS_SECONDS = 0.5  # how often the running stage's elapsed time, rate and ETA are redrawn
# The grammar's token caps of the model stages: the ETA's upper bound until a run of the stage has
# told how many tokens it really takes (then that count is the estimate).
STAGE_TOKEN_BUDGET = {"rois": 32, "synthesis": 512}
MODEL_STAGES = frozenset(STAGE_TOKEN_BUDGET)
monotonic = time.monotonic  # the progress clock; snapshot tests fix it so the picture is reproducible

DEFAULT_HINT = "Press r to retry, or Escape to go back and change the prompt."


@dataclass(frozen=True)
class GenerationRequest:
    prompt: str
    world: str
    preset: str
    seed: int
    # Head counts the user set by group label, re-applied (re-planned, no model call) after generating.
    counts: tuple[tuple[str, int], ...] = ()


def counts_by_index(groups: list[Parsed], counts: dict[str, int]) -> tuple[dict[int, int], list[str]]:
    """The label -> count edits as the pipeline's group index -> count, and the labels no group has now."""
    by_index: dict[int, int] = {}
    found: set[str] = set()
    for index, group in enumerate(groups):
        label = str(group.get("label", ""))
        if label in counts:
            found.add(label)
            if int(counts[label]) != int(group.get("count", 0)):
                by_index[index] = int(counts[label])
    return by_index, [label for label in counts if label not in found]


class TokenBuffer:
    """Collects streamed tokens in the worker and posts the stage text at most every FLUSH_SECONDS.

    A timer flushes what is left when the model pauses, so the last tokens never wait for the next one.
    """

    def __init__(self, post: Callable[[Message], object], interval: float = FLUSH_SECONDS) -> None:
        self._post = post
        self._interval = interval
        self._lock = threading.Lock()
        self._stage = ""
        self._attempt = 1
        self._text: list[str] = []
        self._tokens = 0
        self._dirty = False
        self._last_flush = 0.0
        self._timer: threading.Timer | None = None

    def add(self, stage: str, text: str) -> None:
        with self._lock:
            if stage != self._stage:
                self._flush_locked()
                self._stage, self._attempt, self._text, self._tokens = stage, 1, [], 0
            self._text.append(text)
            self._tokens += 1
            self._dirty = True
            wait = self._interval - (time.monotonic() - self._last_flush)
            if wait <= 0:
                self._flush_locked()
            elif self._timer is None:
                self._timer = threading.Timer(wait, self.flush)
                self._timer.daemon = True
                self._timer.start()

    def flush(self) -> None:
        with self._lock:
            self._flush_locked()

    def restart(self, stage: str, attempt: int, reason: str) -> None:
        """The stage asks the model again: post what the old attempt streamed, then start an empty text."""
        with self._lock:
            self._flush_locked()
            self._stage, self._attempt, self._text, self._tokens = stage, attempt, [], 0
            self._post(msg.AttemptStarted(stage, attempt, reason))

    def _flush_locked(self) -> None:
        if self._timer is not None:
            self._timer.cancel()
            self._timer = None
        if self._dirty:
            self._post(msg.TokensFlushed(self._stage, "".join(self._text), self._tokens, self._attempt))
            self._dirty = False
        self._last_flush = time.monotonic()


@dataclass
class LoadingPart:
    """The part of the stage "loading" loading now (services.session.LoadingProgress, timed here)."""

    doing: str
    index: int
    parts: int
    started: float  # time.monotonic()
    expected: float  # seconds it took last time
    later: float  # seconds the parts after it took


@dataclass
class StageProgress:
    """The running stage, as the table shows it while it runs: elapsed time, tokens, rate and ETA."""

    stage: str
    started: float  # time.monotonic()
    tokens: int = 0
    first_token: float | None = None  # when the first token arrived (before it the model reads the prompt)
    attempt: int = 1  # the model call running now; tokens, rate and ETA are this attempt's
    part: LoadingPart | None = None  # the stage "loading": what it loads now

    def describe(self, now: float, expected_tokens: int | None, bound: bool,
                 expected_first_token: float | None = None) -> tuple[str, str, str]:
        """(time, tokens, detail) cells; `bound` marks an ETA from the token cap, not from experience;
        `expected_first_token` is how long the model read the prompt last time (its ETA till the first token)."""
        elapsed = now - self.started
        time_cell = f"{elapsed:.1f}s"
        retry = f"attempt {self.attempt} · " if self.attempt > 1 else ""
        if self.part is not None:
            part = self.part
            remaining = max(part.expected - (now - part.started), 0.0) + part.later
            return time_cell, "", f"ETA ~{remaining:.0f}s · {part.index}/{part.parts} {part.doing}…"
        if self.tokens == 0 or self.first_token is None:
            if self.stage in MODEL_STAGES:
                if expected_first_token:
                    return time_cell, "", f"{retry}ETA ~{max(expected_first_token - elapsed, 0):.0f}s · reading the prompt…"
                return time_cell, "", retry + "reading the prompt…"
            return time_cell, "", retry.removesuffix(" · ")
        writing = max(now - self.first_token, 1e-3)
        rate = self.tokens / writing
        detail = f"{retry}{rate:.1f} tok/s"
        if expected_tokens and rate > 0:
            remaining = max(expected_tokens - self.tokens, 0) / rate
            detail += f" · ETA {'≤' if bound else '~'}{remaining:.0f}s"
        return time_cell, f"{self.tokens} tok", detail


class StagesTable(DataTable[str]):
    """The stages table: a row cut by the right edge ends with "…" there (←/→ scroll to read the rest)."""

    def render_line(self, y: int) -> Strip:
        strip = super().render_line(y)
        width = self.scrollable_content_region.width
        if width < 2 or self.virtual_size.width <= self.scroll_offset.x + width or strip.cell_length < width:
            return strip
        edge = list(strip.crop(width - 1, width))
        if not edge or not "".join(segment.text for segment in edge).strip():
            return strip  # this row's text ends before the edge
        return Strip.join([strip.crop(0, width - 1), Strip([Segment("…", edge[-1].style)], 1)])


def describe_failure(exc: BaseException) -> tuple[str, str]:
    """The error line and the hint the screens show: the error's own title and hint (grove_tui.errors)."""
    description = describe_error(exc)
    return description.text, description.hint or DEFAULT_HINT


class GenerationScreen(Screen[None]):
    HELP = """\
## Generation

The pipeline's stages run one after another: **Loading** (what the app's warm-up had not loaded
yet: the models, the node index and its embedder, the English reader, the world's planner and fixed
prompt, each with an ETA from the last time it loaded), **RoIs** (the model picks the places the prompt
talks about), **Retrieval** (behavior nodes that fit), **Tree synthesis** (the model writes the
groups and their trees, streamed below), **Post-processing** (trees become BT.CPP XML per agent)
and **Planning** (Theta* waypoints). **Escape** cancels (back to setup, or to the scenario you had
when this is a regenerate); after an error **r** retries. The
running stage shows its elapsed time, tokens, tokens/s and an ETA; **←/→** scroll the table
sideways when a stage's detail is longer than the screen. When the model is asked again (its
answer was cut off or failed the draft check), the output starts afresh under "attempt N (why)".
"""

    BINDINGS = [
        Binding("escape", "cancel", "Cancel", id="generation.cancel", tooltip="Stop generating and go back"),
        Binding("r", "retry", "Retry", id="generation.retry", tooltip="Run the generation again"),
    ]

    def __init__(self, request: GenerationRequest, *, back_to: InspectScreen | None = None) -> None:
        super().__init__()
        self.request = request
        # The inspect screen this generation was asked from (a regenerate): it shows the new scenario,
        # and Escape comes back to it as it was.
        self.back_to = back_to
        self._cancel = threading.Event()
        self._stage = ""
        self._generating = False
        self._started: dict[str, float] = {}
        self._progress: StageProgress | None = None
        self._attempt_header = ""  # the output panel's first line during a retry
        self._switch_interval = sys.getswitchinterval()

    @property
    def grove(self) -> GroveApp:
        return self.app  # type: ignore[return-value]

    def compose(self) -> ComposeResult:
        r = self.request
        yield Static(f"[b]{r.prompt}[/b]\nworld [i]{r.world}[/i] · preset [i]{r.preset}[/i] · seed {r.seed}",
                     id="gen-title", markup=True)
        table = StagesTable(id="stages", cursor_type="none", zebra_stripes=False)
        table.border_title = "Stages"
        yield table
        stream = Static("", id="stream", markup=False)
        stream.border_title = "Model output"
        yield stream
        yield Static("", id="gen-error", markup=False)
        yield Footer(compact=True, show_command_palette=False)

    def on_mount(self) -> None:
        table = self.query_one("#stages", DataTable)
        table.add_column("Stage", key="stage", width=16)
        table.add_column("State", key="state", width=9)
        table.add_column("Time", key="time", width=7)
        table.add_column("Tokens", key="tokens", width=11)
        table.add_column("Detail", key="detail")
        for key, label in STAGES.items():
            table.add_row(label, "·", "", "", "", key=key)
        self.set_interval(PROGRESS_SECONDS, self.show_progress, name="stage-progress")
        # The pipeline thread runs Python (token relay, grammar, post-processing) beside the UI; a
        # short GIL switch interval hands the UI thread the GIL sooner, so keys answer while it works.
        self._switch_interval = sys.getswitchinterval()
        sys.setswitchinterval(UI_SWITCH_INTERVAL)
        self.start()

    def command_entries(self) -> list[CommandEntry]:
        return [
            ("Cancel generation", "Stop the pipeline and return to setup", self.action_cancel),
            ("Retry generation", "Run the pipeline again with the same prompt", self.action_retry),
        ]

    def start(self) -> None:
        self._progress = None
        self._cancel = threading.Event()
        self._generating = True
        self._stage = ""
        error = self.query_one("#gen-error", Static)
        error.update("")
        error.display = False
        table = self.query_one("#stages", DataTable)
        for key in STAGES:
            for column, value in (("state", "·"), ("time", ""), ("tokens", ""), ("detail", "")):
                table.update_cell(key, column, value)
        self._attempt_header = ""
        self.query_one("#stream", Static).update("")
        r = self.request
        self.grove.remember(r.world, r.preset, r.seed)  # the next start of the app opens on these
        self.run_generation(self.request, self._cancel)

    @work(thread=True, exclusive=True, group="generation", exit_on_error=False, description="generating")
    def run_generation(self, request: GenerationRequest, cancel: threading.Event) -> None:
        worker = get_current_worker()
        buffer = TokenBuffer(self.post_message)
        current = {"stage": ""}

        writing: set[str] = set()  # stages whose model has streamed a token

        def on_event(event: Event | LoadingProgress) -> None:
            if isinstance(event, TokenStreamed):
                if event.stage not in writing:
                    # The model process surely exists once it writes (it restarts lazily after a
                    # cancel): from now on it gives way to this process, so keys answer while it writes.
                    writing.add(event.stage)
                    self.grove.session.yield_cpu_to_the_app()
                buffer.add(event.stage, event.text)
            elif isinstance(event, AttemptStarted):
                buffer.restart(event.stage, int(event.attempt), str(event.reason))
            elif isinstance(event, LoadingProgress):
                self.post_message(msg.LoadingPartStarted(event.doing, int(event.index), int(event.parts),
                                                         float(event.expected_seconds), float(event.later_seconds)))
            elif isinstance(event, StageStarted):
                buffer.flush()
                if event.stage in MODEL_STAGES:
                    self.grove.session.yield_cpu_to_the_app()
                current["stage"] = event.stage
                self.post_message(msg.StageStarted(event.stage))
            elif isinstance(event, StageFinished):
                buffer.flush()
                current["stage"] = ""
                self.post_message(msg.StageFinished(
                    event.stage, float(event.seconds), int(event.prompt_tokens or 0),
                    int(event.completion_tokens or 0), str(event.detail or "")))
            if worker.is_cancelled:
                cancel.set()

        note = ""
        try:
            generated = self.grove.session.generate(
                ScenarioRequest(request.world, request.preset, request.prompt, request.seed), on_event=on_event,
                cancel=cancel, show_loading=True)
            if request.counts and not cancel.is_set():
                edits, missing = counts_by_index(list(generated.result.report.get("groups", ())), dict(request.counts))
                if edits:
                    generated = self.grove.session.replan(generated, edits, on_event=on_event, cancel=cancel)
                kept = ", ".join(f"{label} {count}" for label, count in request.counts if label not in missing)
                note = (f"kept counts: {kept}" if kept else "") + (
                    f"{'; ' if kept else ''}no group named {', '.join(missing)} this time" if missing else "")
        except Exception as exc:
            buffer.flush()
            if cancel.is_set() or worker.is_cancelled:
                self.post_message(msg.GenerationStopped(current["stage"]))
            else:
                self.post_message(msg.GenerationFailed(current["stage"], *describe_failure(exc)))
            return
        buffer.flush()
        if cancel.is_set() or worker.is_cancelled:
            self.post_message(msg.GenerationStopped(current["stage"]))
        else:
            self.post_message(msg.GenerationSucceeded(generated, note))

    # messages -------------------------------------------------------------------------------------
    def on_stage_started(self, message: msg.StageStarted) -> None:
        table = self.query_one("#stages", DataTable)
        if message.stage != "loading" and table.get_cell("loading", "state") == "·":
            # The session had everything loaded (the warm-up did it): nothing to wait for.
            table.update_cell("loading", "state", "done")
            table.update_cell("loading", "detail", "all loaded already", update_width=True)
        self._stage = message.stage
        self._attempt_header = ""
        self._progress = StageProgress(message.stage, monotonic())
        if message.stage == "retrieval" and not self.grove.session.embedder_ready():
            self.query_one("#stream", Static).update("loading the embedding model (first generation only)…")
        if message.stage in STAGES:
            self.query_one("#stages", DataTable).update_cell(message.stage, "state", "running")
            self.query_one("#stream", Static).border_title = f"Model output · {STAGES[message.stage]}"

    def on_stage_finished(self, message: msg.StageFinished) -> None:
        if message.stage not in STAGES:
            return
        table = self.query_one("#stages", DataTable)
        if self._progress is not None and self._progress.stage == message.stage:
            self._progress = None
        if message.completion_tokens:
            # What this stage really took: the next run's ETA expects as many tokens.
            self.grove.stage_tokens[message.stage] = message.completion_tokens
        table.update_cell(message.stage, "state", "done")
        table.update_cell(message.stage, "time", f"{message.seconds:.2f}s")
        tokens = message.prompt_tokens + message.completion_tokens
        table.update_cell(message.stage, "tokens", f"{message.prompt_tokens}+{message.completion_tokens}" if tokens else "")
        table.update_cell(message.stage, "detail", message.detail, update_width=True)

    def on_loading_part_started(self, message: msg.LoadingPartStarted) -> None:
        progress = self._progress
        if progress is None or progress.stage != "loading":
            return
        progress.part = LoadingPart(message.doing, message.index, message.parts, monotonic(), message.expected_seconds,
                                    message.later_seconds)
        self.query_one("#stream", Static).update(f"{message.doing}… (the app's warm-up does this at start; "
                                                 "a generation asked before it is done waits for it)")
        self.show_progress()

    def on_attempt_started(self, message: msg.AttemptStarted) -> None:
        """A retry: the output panel starts a fresh section headed by why, the table counts the attempt."""
        self._attempt_header = f"── attempt {message.attempt} ({shorten(message.reason, ATTEMPT_REASON_CHARS)}) ──\n"
        self.query_one("#stream", Static).update(self._attempt_header)
        if message.stage in STAGES:
            self.query_one("#stream", Static).border_title = (
                f"Model output · {STAGES[message.stage]} · attempt {message.attempt}")
        progress = self._progress
        if progress is not None and progress.stage == message.stage:
            progress.attempt = message.attempt
            progress.tokens = 0
            progress.first_token = None
        self.show_progress()

    def on_tokens_flushed(self, message: msg.TokensFlushed) -> None:
        # The panel's size is set by the layout (1fr), never by its text: repaint it alone, without a
        # layout pass over the whole screen 20 times a second while the model writes.
        self.query_one("#stream", Static).update(self._attempt_header + message.text[-STREAM_TAIL_CHARS:],
                                                 layout=False)
        progress = self._progress
        if progress is not None and progress.stage == message.stage and message.tokens:
            if progress.first_token is None:
                progress.first_token = monotonic()
                # How long the model read the prompt: the next run's ETA until its first token.
                self.grove.stage_first_token[message.stage] = progress.first_token - progress.started
            progress.tokens = message.tokens

    def show_progress(self) -> None:
        progress = self._progress
        if progress is None or not self._generating or progress.stage not in STAGES:
            return
        learned = self.grove.stage_tokens.get(progress.stage)
        expected = learned if learned else STAGE_TOKEN_BUDGET.get(progress.stage)
        time_cell, tokens, detail = progress.describe(monotonic(), expected, bound=not learned,
                                                      expected_first_token=self.grove.stage_first_token.get(progress.stage))
        table = self.query_one("#stages", DataTable)
        table.update_cell(progress.stage, "time", time_cell)
        table.update_cell(progress.stage, "tokens", tokens)
        table.update_cell(progress.stage, "detail", detail, update_width=True)

    def on_generation_succeeded(self, message: msg.GenerationSucceeded) -> None:
        from grove_tui.tui.screens.inspect import InspectScreen

        self._generating = False
        self.grove.generated = message.generated
        back_to = self.back_to
        if back_to is not None and back_to in self.app.screen_stack:
            self.app.pop_screen()
            back_to.show_scenario(message.generated, dict(self.request.counts))
        else:
            self.app.switch_screen(InspectScreen(message.generated, count_edits=dict(self.request.counts)))
        if message.note:
            self.app.notify(message.note, title="Counts", timeout=6)

    def on_generation_failed(self, message: msg.GenerationFailed) -> None:
        self._generating = False
        self._progress = None
        if message.stage in STAGES:
            self.query_one("#stages", DataTable).update_cell(message.stage, "state", "failed")
        error = self.query_one("#gen-error", Static)
        where = STAGES.get(message.stage, "generation")
        error.update(f"✗ {where} failed\n{message.error}\n→ {message.hint}")
        error.display = True

    def on_generation_stopped(self, message: msg.GenerationStopped) -> None:
        self._generating = False
        self.app.pop_screen()
        if self.back_to is not None:
            self.notify("Generation cancelled: back to the scenario you had.", title="Generation")
        else:
            self.notify("Generation cancelled.", title="Generation")

    def on_unmount(self) -> None:
        # Leaving the screen (or quitting) stops the pipeline instead of letting it run unseen.
        self._cancel.set()
        sys.setswitchinterval(self._switch_interval)

    # actions --------------------------------------------------------------------------------------
    def action_cancel(self) -> None:
        if self._generating:
            self._cancel.set()
            self.workers.cancel_group(self, "generation")
            if self._stage in STAGES:
                self.query_one("#stages", DataTable).update_cell(self._stage, "state", "stopping")
            return
        self.app.pop_screen()

    def action_retry(self) -> None:
        if not self._generating:
            self.start()
