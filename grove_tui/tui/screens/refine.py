"""The follow-up dialog: what a sentence would change (a diff of groups and the robot), then applying it.

Opened by the inspect screen's follow-up box. A worker reads the sentence against the scenario
(`session.read_refinement`, no model); a name that could mean several groups ("the nurse" with two
nurse groups) is asked about first, one numbered line per group. The diff is shown before anything
runs: **Enter** applies it (a worker runs `session.refine`: the model for new and changed groups only,
stage by stage on the status line), **Escape** cancels. The dialog returns the refined scenario.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass
from typing import TYPE_CHECKING

from textual import events, on, work
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical, VerticalScroll
from textual.message import Message
from textual.screen import ModalScreen
from textual.widgets import Button, Static
from textual.worker import get_current_worker

from grove_tui.errors import AmbiguousEditError
from grove_tui.services.session import GeneratedScenario
from grove_tui.tui.screens.generation import STAGES, describe_failure

if TYPE_CHECKING:
    from grove_tui.services.domain import Refinement
    from grove_tui.services.session import Event, LoadingProgress
    from grove_tui.tui.app import GroveApp

MAX_CHOICES = 9  # one key each, 1..9


class RefineScreen(ModalScreen[GeneratedScenario | None]):
    """Returns the refined scenario, or None when the user cancels or nothing can be applied."""

    HELP = """\
## Follow-up

What the sentence would change, before anything runs: `+` a group added, `~` a group changed (old →
new), `-` a group removed, and the robot; `=` how many groups stay exactly as they are. **Enter**
applies it (only new and changed groups are generated), **Escape** cancels. When a name could mean
several groups, press the number of the one you mean.
"""

    DEFAULT_CSS = """
    RefineScreen {
        align: center middle;
    }
    #refine-dialog {
        width: 90%;
        max-width: 76;
        height: auto;
        max-height: 100%;
        border: thick $accent;
        background: $panel;
        padding: 0 1;
    }
    #refine-title {
        text-style: bold;
    }
    #refine-scroll {
        height: auto;
        max-height: 12;
    }
    #refine-status {
        height: auto;
        color: $text-muted;
    }
    #refine-buttons {
        height: 3;
        align-horizontal: right;
    }
    #refine-buttons Button {
        margin-left: 1;
    }
    """

    BINDINGS = [
        Binding("escape", "cancel", "Cancel", id="refine.cancel", tooltip="Keep the scenario as it is"),
        Binding("enter", "apply", "Apply", id="refine.apply", tooltip="Apply the follow-up", priority=True),
        Binding("f1", "app.help", "Help", id="refine.help", tooltip="Help for this dialog and its keys"),
    ]

    @dataclass
    class Read(Message):
        refinement: Refinement

    @dataclass
    class Asked(Message):
        phrase: str
        options: tuple[tuple[int, str], ...]

    @dataclass
    class Applied(Message):
        generated: GeneratedScenario

    @dataclass
    class Failed(Message):
        error: str
        hint: str

    @dataclass
    class Progress(Message):
        text: str

    def __init__(self, generated: GeneratedScenario, sentence: str) -> None:
        super().__init__()
        self.generated = generated
        self.sentence = sentence
        self.choices: list[int] = []
        self.refinement: Refinement | None = None
        self.options: tuple[tuple[int, str], ...] = ()
        self.state = "reading"  # reading, asking, ready, applying, failed
        self._cancel = threading.Event()
        self._tokens = 0

    @property
    def grove(self) -> GroveApp:
        return self.app  # type: ignore[return-value]

    def compose(self) -> ComposeResult:
        with Vertical(id="refine-dialog"):
            yield Static(f"Follow-up: {self.sentence}", id="refine-title", markup=False)
            with VerticalScroll(id="refine-scroll"):
                yield Static("Reading the sentence…", id="refine-diff", markup=False)
            yield Static("", id="refine-status", markup=False)
            with Horizontal(id="refine-buttons"):
                yield Button("Apply (Enter)", id="refine-apply", variant="primary", disabled=True)
                yield Button("Cancel (Esc)", id="refine-cancel")

    def on_mount(self) -> None:
        self.query_one("#refine-cancel", Button).focus()
        self.read(tuple(self.choices))

    # reading ---------------------------------------------------------------------------------------------
    @work(thread=True, exclusive=True, group="refine-read", exit_on_error=False, description="reading the follow-up")
    def read(self, choices: tuple[int, ...]) -> None:
        try:
            refinement = self.grove.session.read_refinement(self.generated, self.sentence, choices=choices)
        except AmbiguousEditError as exc:
            phrase, options = exc.choices[0]
            self.post_message(self.Asked(phrase, options))
            return
        except Exception as exc:  # noqa: BLE001 - every failure is shown in the dialog with its hint
            self.post_message(self.Failed(*describe_failure(exc)))
            return
        self.post_message(self.Read(refinement))

    @on(Asked)
    def asked(self, message: Asked) -> None:
        self.state = "asking"
        self.options = message.options[:MAX_CHOICES]
        lines = [f"Which group is '{message.phrase}'?"]
        lines += [f"  {k}  {text}" for k, (_, text) in enumerate(self.options, start=1)]
        self.query_one("#refine-diff", Static).update("\n".join(lines))
        self._status(f"Press 1-{len(self.options)} · Escape cancels · F1 help")

    def on_key(self, event: events.Key) -> None:
        if self.state != "asking" or not event.character or not event.character.isdigit():
            return
        number = int(event.character)
        if 1 <= number <= len(self.options):
            event.stop()
            self.choices.append(self.options[number - 1][0])
            self.state = "reading"
            self.query_one("#refine-diff", Static).update("Reading the sentence…")
            self.read(tuple(self.choices))

    @on(Read)
    def read_done(self, message: Read) -> None:
        self.refinement = message.refinement
        self.state = "ready"
        self.query_one("#refine-diff", Static).update("\n".join(message.refinement.diff.lines()))
        written = sum(1 for g in message.refinement.groups if g.regenerate)
        model = f"the model writes {written} group(s)" if written else "no model call"
        self._status(f"Enter applies ({model}) · Escape cancels")
        apply = self.query_one("#refine-apply", Button)
        apply.disabled = False
        apply.focus()

    # applying --------------------------------------------------------------------------------------------
    @on(Button.Pressed, "#refine-apply")
    def action_apply(self) -> None:
        if self.state != "ready" or self.refinement is None:  # ready: the refinement is read
            return
        self.state = "applying"
        self.query_one("#refine-apply", Button).disabled = True
        self._status("Applying…")
        self._cancel = threading.Event()
        self.apply(self.refinement, self._cancel)

    @work(thread=True, exclusive=True, group="refine-apply", exit_on_error=False, description="applying the follow-up")
    def apply(self, refinement: Refinement, cancel: threading.Event) -> None:
        worker = get_current_worker()
        try:
            generated = self.grove.session.refine(self.generated, refinement, on_event=self._event, cancel=cancel)
        except Exception as exc:  # noqa: BLE001 - shown in the dialog with its hint
            if not (cancel.is_set() or worker.is_cancelled):
                self.post_message(self.Failed(*describe_failure(exc)))
            return
        if not (cancel.is_set() or worker.is_cancelled):
            self.post_message(self.Applied(generated))

    def _event(self, event: Event | LoadingProgress) -> None:
        """Pipeline events, in the worker's thread: a line of progress for the UI thread."""
        from grove_tui.services.session import StageStarted, TokenStreamed

        if isinstance(event, StageStarted):
            self._tokens = 0
            self.post_message(self.Progress(f"{STAGES.get(event.stage, event.stage)}…"))
        elif isinstance(event, TokenStreamed):
            self._tokens += 1
            if self._tokens % 8 == 0:
                self.post_message(self.Progress(f"{STAGES.get(event.stage, event.stage)}: {self._tokens} tokens"))

    @on(Progress)
    def progress(self, message: Progress) -> None:
        if self.state == "applying":
            self._status(f"{message.text} · Escape cancels")

    @on(Applied)
    def applied(self, message: Applied) -> None:
        self.state = "done"
        self.dismiss(message.generated)

    @on(Failed)
    def failed(self, message: Failed) -> None:
        self.state = "failed"
        self.query_one("#refine-diff", Static).update(f"✗ {message.error}\n→ {message.hint}")
        self._status("Escape closes · edit the sentence in the follow-up box and press Enter again")
        self.query_one("#refine-apply", Button).disabled = True
        self.query_one("#refine-cancel", Button).focus()

    @on(Button.Pressed, "#refine-cancel")
    def action_cancel(self) -> None:
        if self.state == "applying":
            self._cancel.set()
            self.workers.cancel_group(self, "refine-apply")
            self.notify("Follow-up cancelled.", title="Follow-up", timeout=3)
        self.dismiss(None)

    def _status(self, text: str) -> None:
        self.query_one("#refine-status", Static).update(text)

    def on_unmount(self) -> None:
        self._cancel.set()
