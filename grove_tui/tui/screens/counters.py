"""Every counter of the running simulation in a dialog (`m`), for when the side column folds them."""

from __future__ import annotations

from typing import TYPE_CHECKING

from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.screen import ModalScreen
from textual.widgets import Static

if TYPE_CHECKING:
    from grove_tui.tui.screens.sim_controller import Counters


class CountersScreen(ModalScreen[None]):
    """metrics.json's numbers for the run so far, kept up to date while the run plays behind it."""

    HELP = """\\
## Counters

metrics.json's numbers for the run up to the time in the title, under metrics.json's names: what
`grove metrics` gives for the run exported now. They follow the run while this dialog is open.
**Escape** or **m** closes it.
"""

    BINDINGS = [
        Binding("escape,m", "dismiss", "Close", id="counters.close", tooltip="Back to the simulation"),
        Binding("f1", "app.help", "Help", id="counters.help", tooltip="Help for this dialog"),
    ]

    def __init__(self, counters: Counters | None) -> None:
        super().__init__()
        self._counters = counters

    def compose(self) -> ComposeResult:
        with Vertical(id="counters-dialog"):
            yield Static("", id="counters-all", markup=False)

    def on_mount(self) -> None:
        self.show(self._counters)

    def show(self, counters: Counters | None) -> None:
        from grove_tui.tui.screens.simulation import counter_lines

        self._counters = counters
        dialog = self.query_one("#counters-dialog")
        text = self.query_one("#counters-all", Static)
        if counters is None:
            dialog.border_title = "Counters"
            text.update("No frame measured yet: press space to play.")
            return
        dialog.border_title = f"Counters · metrics.json at t = {counters.t:.2f} s"
        text.update(f"✗ {counters.error}" if counters.error else "\n".join(counter_lines(counters.values, 44)))
