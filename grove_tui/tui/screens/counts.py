"""Edit counts: a new head count per group, re-planned without the model (post-processing and planning only)."""

from __future__ import annotations

import threading
from dataclasses import dataclass
from typing import TYPE_CHECKING

from textual import on, work
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical, VerticalScroll
from textual.message import Message
from textual.screen import ModalScreen
from textual.widgets import Button, Input, Label, Static
from textual.worker import get_current_worker

from grove_tui.services.session import GeneratedScenario
from grove_tui.tui.screens.generation import describe_failure
from grove_tui.tui.widgets.prompt_input import ReadlineInput

if TYPE_CHECKING:
    from grove_tui.jsontypes import Parsed
    from grove_tui.tui.app import GroveApp

COUNT_DIGITS = 3
READY = "Enter applies · Tab next count · Escape cancels · F1 help"
def group_rows(generated: GeneratedScenario) -> list[Parsed]:
    """The groups as the pipeline reported them: index order is the order `replan` counts refer to."""
    return [dict(g) for g in generated.result.report.get("groups", ())]


class CountsScreen(ModalScreen[GeneratedScenario | None]):
    """Returns the re-planned scenario, or None when the user cancels or changes nothing."""

    HELP = """\
## Edit counts

One line per group: its label, where it starts and how many people it has. Type new numbers,
then **Enter** (or **Apply**) re-plans the scenario with the same behavior trees: post-processing
and planning run again, the model does not. **Tab** moves between the counts, **Escape** cancels.
"""

    BINDINGS = [
        Binding("escape", "cancel", "Cancel", id="counts.cancel", tooltip="Keep the scenario as it is"),
        # A modal screen hides the app's own bindings: F1 help has to be bound here too.
        Binding("f1", "app.help", "Help", id="counts.help", tooltip="Help for this dialog and its keys"),
    ]

    @dataclass
    class Replanned(Message):
        """The worker re-planned the scenario."""

        dialog: CountsScreen
        generated: GeneratedScenario

        @property
        def control(self) -> CountsScreen:
            return self.dialog

    @dataclass
    class ReplanFailed(Message):
        """The worker could not re-plan: the error and what to do about it."""

        dialog: CountsScreen
        error: str
        hint: str

        @property
        def control(self) -> CountsScreen:
            return self.dialog

    def __init__(self, generated: GeneratedScenario) -> None:
        super().__init__()
        self.generated = generated
        self.groups = group_rows(generated)
        self._cancel = threading.Event()
        self.replanning = False

    @property
    def grove(self) -> GroveApp:
        return self.app  # type: ignore[return-value]

    def compose(self) -> ComposeResult:
        with Vertical(id="counts-dialog"):
            yield Static("Edit counts and re-plan", id="counts-title")
            with VerticalScroll(id="counts-rows"):
                for index, group in enumerate(self.groups):
                    with Horizontal(classes="counts-row"):
                        yield Label(f"{group['label']}", classes="counts-label", markup=False)
                        yield Label(f"in {group['spawn']}", classes="counts-spawn", markup=False)
                        field = ReadlineInput(str(group["count"]), id=f"count-{index}", restrict=r"[0-9]*",
                                      max_length=COUNT_DIGITS, classes="counts-input",
                                      tooltip=f"People in group '{group['label']}'")
                        yield field
            yield Static("", id="counts-status", markup=False)
            yield Static("", id="counts-error", markup=False)
            with Horizontal(id="counts-buttons"):
                yield Button("Apply", id="counts-apply", variant="primary")
                yield Button("Cancel", id="counts-cancel")

    def on_mount(self) -> None:
        self.query_one("#counts-error", Static).display = False
        inputs = self.query(Input)
        if inputs:
            inputs.first().focus()
        else:
            self._show_error("this scenario reports no groups to edit", "Press Escape and regenerate it.")
        self.query_one("#counts-status", Static).update(READY)

    # reading the form --------------------------------------------------------------------------------
    def edited_counts(self) -> dict[int, int] | None:
        """Counts that differ from the scenario's; None (with the error shown) when a field is empty."""
        counts: dict[int, int] = {}
        for index, group in enumerate(self.groups):
            text = self.query_one(f"#count-{index}", Input).value.strip()
            if not text:
                self._show_error(f"group '{group['label']}' has no count", "Type a number of people, at least 1.")
                self.query_one(f"#count-{index}", Input).focus()
                return None
            if int(text) != int(group["count"]):
                counts[index] = int(text)
        return counts

    def _show_error(self, error: str, hint: str) -> None:
        panel = self.query_one("#counts-error", Static)
        panel.update(f"✗ {error}\n→ {hint}")
        panel.display = True

    def _set_busy(self, busy: bool) -> None:
        self.replanning = busy
        self.query_one("#counts-apply", Button).disabled = busy
        for field in self.query(Input):
            field.disabled = busy
        self.query_one("#counts-status", Static).update(
            "Re-planning… Escape cancels" if busy else READY)

    # actions ------------------------------------------------------------------------------------------
    @on(Input.Submitted, ".counts-input")
    @on(Button.Pressed, "#counts-apply")
    def apply_counts(self) -> None:
        if self.replanning:
            return
        counts = self.edited_counts()
        if counts is None:
            return
        if not counts:
            self.notify("Counts unchanged.", title="Edit counts", timeout=3)
            self.dismiss(None)
            return
        self.query_one("#counts-error", Static).display = False
        self._set_busy(True)
        self._cancel = threading.Event()
        self.run_replan(self.generated, counts, self._cancel)

    @on(Button.Pressed, "#counts-cancel")
    def action_cancel(self) -> None:
        if self.replanning:
            self._cancel.set()
            self.workers.cancel_group(self, "generation")
            self.notify("Re-planning cancelled.", title="Edit counts", timeout=3)
        self.dismiss(None)

    @work(thread=True, exclusive=True, group="generation", exit_on_error=False, description="re-planning")
    def run_replan(self, generated: GeneratedScenario, counts: dict[int, int], cancel: threading.Event) -> None:
        worker = get_current_worker()
        try:
            result = self.grove.session.replan(generated, counts, cancel=cancel)
        except Exception as exc:
            if not (cancel.is_set() or worker.is_cancelled):
                self.post_message(self.ReplanFailed(self, *describe_failure(exc)))
            return
        if not (cancel.is_set() or worker.is_cancelled):
            self.post_message(self.Replanned(self, result))

    @on(Replanned)
    def replanned(self, message: Replanned) -> None:
        self.replanning = False
        self.dismiss(message.generated)

    @on(ReplanFailed)
    def replan_failed(self, message: ReplanFailed) -> None:
        self._set_busy(False)
        self._show_error(message.error, message.hint)
        self.query(Input).first().focus()

    def on_unmount(self) -> None:
        self._cancel.set()
