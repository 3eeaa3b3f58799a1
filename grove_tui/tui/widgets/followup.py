"""The follow-up box of the inspect screen: one line where a sentence edits the scenario.

"add a cleaner mopping the corridor", "make the queue twice as long", "the visitors walk to the
cafeteria instead", "remove the cleaner", "no robot": Enter posts `FollowupBox.Submitted`, and the
inspect screen shows what would change before anything is applied (screens/refine.py). Up/Down walk
through the follow-ups typed before; Escape gives the keys back to the trees.
"""

from __future__ import annotations

from dataclasses import dataclass

from textual import on
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal
from textual.message import Message
from textual.widgets import Input, Label

from grove_tui.tui.widgets.prompt_input import ReadlineInput

PLACEHOLDER = "f: follow-up, e.g. add two guards at the entrance"


class FollowupInput(ReadlineInput):  # readline's keys, as every text field of the app
    HELP = """\
## Follow-up

A sentence that edits the scenario: add groups (*"add a cleaner mopping the corridor"*, *"plus two
more nurses"*), change one by its name or place (*"the visitors walk to the cafeteria instead"*,
*"make the queue twice as long"*, *"the family walks slowly"*), remove one (*"remove the cleaner"*),
or the robot (*"the robot waits at reception"*, *"no robot"*). **Enter** shows what would change,
before it is applied; groups the sentence does not name stay exactly as they are. **Up/Down** walk
through earlier follow-ups, **Escape** goes back to the trees. **ctrl+z** / **ctrl+y** on the
inspect screen undo and redo an edit.
"""

    BINDINGS = [
        Binding("up", "history(-1)", "Older follow-up", show=False, id="followup.history_back"),
        Binding("down", "history(1)", "Newer follow-up", show=False, id="followup.history_forward"),
        Binding("escape", "leave", "Back to the trees", id="followup.leave", tooltip="Give the keys back to the trees"),
    ]

    @dataclass
    class Left(Message):
        """Escape: the user is done typing."""

    def __init__(self, *, placeholder: str = "", id: str | None = None, max_length: int = 0) -> None:
        super().__init__(placeholder=placeholder, id=id, max_length=max_length)
        self.history: list[str] = []
        self._index: int | None = None

    def remember(self, sentence: str) -> None:
        if not self.history or self.history[-1] != sentence:
            self.history.append(sentence)
        self._index = None

    def action_history(self, step: int) -> None:
        if not self.history:
            return
        index = (len(self.history) if self._index is None else self._index) + step
        if index >= len(self.history):
            self._index, self.value = None, ""
        else:
            self._index = max(0, index)
            self.value = self.history[self._index]
        self.cursor_position = len(self.value)

    def action_leave(self) -> None:
        self.post_message(self.Left())


class FollowupBox(Horizontal):
    """A label and the follow-up line; `Submitted` carries the sentence typed."""

    # One line, borderless: at 80x24 the trees and the map keep their rows.
    DEFAULT_CSS = """
    FollowupBox {
        height: 1;
        width: 1fr;
    }
    FollowupBox > #followup-label {
        width: auto;
        padding: 0 1 0 0;
        color: $text-muted;
    }
    FollowupBox > FollowupInput {
        width: 1fr;
        height: 1;
        border: none;
        padding: 0;
    }
    FollowupBox > FollowupInput:focus {
        background: $boost;
    }
    FollowupBox:focus-within > #followup-label {
        color: $accent;
        text-style: bold;
    }
    """

    @dataclass
    class Submitted(Message):
        sentence: str

    def compose(self) -> ComposeResult:
        yield Label("follow-up ›", id="followup-label")
        yield FollowupInput(placeholder=PLACEHOLDER, id="followup-input", max_length=500)

    @property
    def input(self) -> FollowupInput:
        return self.query_one(FollowupInput)

    def focus_input(self) -> None:
        self.input.focus()

    @on(Input.Submitted, "#followup-input")
    def submitted(self, event: Input.Submitted) -> None:
        event.stop()
        sentence = " ".join(event.value.split())
        if not sentence:
            return
        self.input.remember(sentence)
        self.post_message(self.Submitted(sentence))

    def clear(self) -> None:
        self.input.value = ""
