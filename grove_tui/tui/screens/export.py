"""Export result: which files were written, and where."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical, VerticalScroll
from textual.screen import ModalScreen
from textual.widgets import Button, ProgressBar, Static

if TYPE_CHECKING:
    from grove_tui.services.exporting import ExportedFile

NOTE_CHARS = 160


def describe(files: list[ExportedFile], out_dir: Path) -> str:
    """One line per export, paths relative to the export folder (shown once above them)."""
    lines = []
    for exported in files:
        try:
            shown = str(Path(exported.path).relative_to(out_dir)) or "."
        except ValueError:
            shown = str(exported.path)
        note = exported.note if len(exported.note) <= NOTE_CHARS else exported.note[: NOTE_CHARS - 1] + "…"
        if note.startswith(("failed", "not ")):
            lines.append(f"✗ {exported.kind:<12} {note}")
        else:
            lines.append(f"✓ {exported.kind:<12} {shown}" + (f"  {note}" if note else ""))
    return "\n".join(lines) or "nothing was exported"


class ExportResultScreen(ModalScreen[None]):
    HELP = "## Export\n\nThe files just written, relative to the export folder. **Enter** or **Escape** closes this dialog."

    BINDINGS = [Binding("escape,enter", "dismiss", "Close", id="export.close", tooltip="Close this dialog")]

    def __init__(self, files: list[ExportedFile], out_dir: Path) -> None:
        super().__init__()
        self.files = files
        self.out_dir = out_dir

    def compose(self) -> ComposeResult:
        with Vertical(id="export-dialog"):
            yield Static(f"Exported to {self.out_dir}", id="export-title", markup=False)
            with VerticalScroll(id="export-scroll"):
                yield Static(describe(self.files, self.out_dir), id="export-files", markup=False)
            yield Button("Close", id="export-close", variant="primary")

    def on_mount(self) -> None:
        self.query_one("#export-close", Button).focus()

    def on_button_pressed(self) -> None:
        self.dismiss()


class ExportProgressScreen(ModalScreen[None]):
    """Shown while exporting: which format is being written, n of N. The caller dismisses it when done."""

    HELP = """\
## Exporting

The formats are written one after another into a new folder of the export directory; the bar
moves as each starts. The simulation is paused meanwhile and resumes when the export is done.
"""

    BINDINGS = [Binding("f1", "app.help", "Help", id="export_progress.help", tooltip="Help for this dialog")]

    def __init__(self, what: str) -> None:
        super().__init__()
        self.what = what
        self.kind = ""

    def compose(self) -> ComposeResult:
        with Vertical(id="export-progress-dialog"):
            yield Static(f"Exporting {self.what}…", id="export-progress-title", markup=False)
            yield ProgressBar(total=None, show_eta=False, id="export-progress-bar")
            yield Static("starting", id="export-progress-step", markup=False)

    def advance(self, kind: str, index: int, total: int) -> None:
        self.kind = kind
        self.query_one("#export-progress-bar", ProgressBar).update(total=total, progress=index)
        self.query_one("#export-progress-step", Static).update(f"{index + 1}/{total} · {kind}")
