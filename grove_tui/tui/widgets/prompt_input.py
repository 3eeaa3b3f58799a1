"""The prompt box: an Input with Up/Down history."""

from __future__ import annotations

from textual.binding import Binding
from textual.widgets import Input


class PromptInput(Input):
    HELP = """\
## Prompt

Describe the crowd in one sentence, e.g. *"ten patients queue at the pharmacy while a robot
crosses the hall"*. **Enter** generates; **Up/Down** walk through earlier prompts.
"""

    BINDINGS = [
        Binding("up", "history(-1)", "Older prompt", show=False, id="prompt.history_back"),
        Binding("down", "history(1)", "Newer prompt", show=False, id="prompt.history_forward"),
    ]

    def __init__(self, history: list[str] | None = None, **kwargs: object) -> None:
        super().__init__(**kwargs)  # type: ignore[arg-type]
        self.history = history if history is not None else []
        self._history_index: int | None = None
        self._draft = ""

    def action_history(self, step: int) -> None:
        if not self.history:
            return
        if self._history_index is None:
            if step > 0:
                return
            self._draft = self.value
            index = len(self.history) - 1
        else:
            index = self._history_index + step
        if index >= len(self.history):
            self._history_index = None
            self.value = self._draft
        else:
            self._history_index = max(0, index)
            self.value = self.history[self._history_index]
        self.cursor_position = len(self.value)

    def reset_history_position(self) -> None:
        self._history_index = None
