"""Export result: which files were written, and where."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.screen import ModalScreen
from textual.widgets import Button, Static


class ExportResultScreen(ModalScreen[None]):
    HELP = "## Export\n\nThe files just written. **Enter** or **Escape** closes this dialog."

    BINDINGS = [Binding("escape,enter", "dismiss", "Close", id="export.close", tooltip="Close this dialog")]

    def __init__(self, files: list[Any], out_dir: Path) -> None:
        super().__init__()
        self.files = files
        self.out_dir = out_dir

    def compose(self) -> ComposeResult:
        lines = [f"{f.kind:<13} {f.path}" + (f"  ({f.note})" if f.note else "") for f in self.files]
        lines = lines or ["nothing was exported"]
        with Vertical(id="export-dialog"):
            yield Static(f"Exported to {self.out_dir}", id="export-title", markup=False)
            yield Static("\n".join(lines), id="export-files", markup=False)
            yield Button("Close", id="export-close", variant="primary")

    def on_mount(self) -> None:
        self.query_one("#export-close", Button).focus()

    def on_button_pressed(self) -> None:
        self.dismiss()
