"""Recent runs: every bundle saved under the runs folder, newest first; Enter reopens one in inspect."""

from __future__ import annotations

import time
from pathlib import Path
from typing import TYPE_CHECKING

from rich.text import Text
from textual import on, work
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.message import Message
from textual.screen import ModalScreen
from textual.widgets import OptionList, Static
from textual.widgets.option_list import Option

if TYPE_CHECKING:
    from grove_tui.services.runs import RunInfo
    from grove_tui.tui.app import GroveApp


def shown_path(path: Path) -> str:
    """A path as a user types it: the home folder as ~ (shorter, and the same on every account)."""
    try:
        return "~/" + str(Path(path).relative_to(Path.home()))
    except ValueError:
        return str(path)


def run_label(run: RunInfo, now: float | None = None) -> Text:
    """Two lines: the prompt, then when, where, seed and size (a broken bundle says why instead)."""
    when = time.strftime("%Y-%m-%d %H:%M", time.localtime(run.modified))
    label = Text(no_wrap=True, overflow="ellipsis")
    if run.error:
        label.append(run.path.name, style="bold")
        label.append(f"\n{when} · cannot open: {run.error}", style="red")
        return label
    label.append(run.prompt or "(no prompt)", style="bold")
    simulated = " · simulated" if run.simulated else ""
    label.append(f"\n{when} · {run.world} · {run.preset} · seed {run.seed} · {run.agents} agents{simulated}",
                 style="dim")
    return label


class RecentRunsScreen(ModalScreen[Path | None]):
    """Returns the bundle folder to open, or None when the user closes the list."""

    HELP = """\
## Recent runs

Every scenario the app generated is saved as a bundle under the runs folder. The newest are listed
first; **Enter** opens one in the inspect screen (trees, map, play, export) as it was saved.
**Escape** closes the list.
"""

    BINDINGS = [
        Binding("escape", "close", "Close", id="recent.close", tooltip="Close the list"),
        # A modal screen hides the app's own bindings: F1 help has to be bound here too.
        Binding("f1", "app.help", "Help", id="recent.help", tooltip="Help for this list and its keys"),
    ]

    class Listed(Message):
        def __init__(self, runs: list[RunInfo], error: str = "") -> None:
            super().__init__()
            self.runs = runs
            self.error = error

    def __init__(self) -> None:
        super().__init__()
        self.runs: list[RunInfo] = []

    @property
    def grove(self) -> GroveApp:
        return self.app  # type: ignore[return-value]

    def compose(self) -> ComposeResult:
        with Vertical(id="recent-dialog"):
            yield Static(f"Recent runs · {shown_path(self.grove.session.runs_dir)}", id="recent-title", markup=False)
            runs = OptionList(id="recent-runs")
            runs.border_title = "Enter opens · Esc closes"
            yield runs
            yield Static("looking for saved runs…", id="recent-status", markup=False)

    def on_mount(self) -> None:
        self.query_one("#recent-runs", OptionList).focus()
        self.list_runs()

    @work(thread=True, exclusive=True, group="recent", exit_on_error=False, description="listing runs")
    def list_runs(self) -> None:
        try:
            runs = self.grove.session.recent_runs()
        except Exception as exc:  # an unreadable runs folder must say so in the list, not kill the app
            self.post_message(self.Listed([], f"cannot list runs: {type(exc).__name__}: {exc}"))
            return
        self.post_message(self.Listed(runs))

    def on_recent_runs_screen_listed(self, message: Listed) -> None:
        self.runs = message.runs
        options = self.query_one("#recent-runs", OptionList)
        options.clear_options()
        options.add_options([Option(run_label(run), id=str(run.path), disabled=bool(run.error)) for run in self.runs])
        status = self.query_one("#recent-status", Static)
        if message.error:
            status.update(message.error)
        elif not self.runs:
            status.update("No saved runs yet: generate a scenario first.")
        else:
            status.update(f"{len(self.runs)} run(s), newest first")
            options.highlighted = next((i for i, run in enumerate(self.runs) if not run.error), None)

    @on(OptionList.OptionSelected, "#recent-runs")
    def run_selected(self, event: OptionList.OptionSelected) -> None:
        if event.option.id:
            self.dismiss(Path(event.option.id))

    def action_close(self) -> None:
        self.dismiss(None)
