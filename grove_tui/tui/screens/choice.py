"""A small question dialog: a message and a few answers, each with its own key and button."""

from __future__ import annotations

from dataclasses import dataclass

from textual import events, on
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical
from textual.screen import ModalScreen
from textual.widgets import Button, Static


@dataclass(frozen=True)
class Choice:
    key: str  # a single key, also shown on the button
    label: str
    value: str


class ChoiceScreen(ModalScreen[str | None]):
    """Returns the chosen answer's value; Escape returns None (the caller treats it as "do nothing")."""

    HELP = """\
## Question

Press the key shown on an answer's button (or Tab to it and Enter). **Escape** answers nothing and
leaves everything as it was.
"""

    BINDINGS = [
        Binding("escape", "answer('')", "Cancel", id="choice.cancel", tooltip="Leave everything as it was"),
        Binding("f1", "app.help", "Help", id="choice.help", tooltip="Help for this dialog"),
    ]

    def __init__(self, title: str, text: str, choices: list[Choice]) -> None:
        super().__init__()
        self.title_text = title
        self.text = text
        self.choices = choices

    def compose(self) -> ComposeResult:
        with Vertical(id="choice-dialog"):
            yield Static(self.title_text, id="choice-title", markup=False)
            yield Static(self.text, id="choice-text", markup=False)
            with Horizontal(id="choice-buttons"):
                for index, choice in enumerate(self.choices):
                    yield Button(f"{choice.label} ({choice.key})", id=f"choice-{choice.value}",
                                 variant="primary" if index == 0 else "default")

    def on_mount(self) -> None:
        self.query(Button).first().focus()

    def on_key(self, event: events.Key) -> None:
        for choice in self.choices:
            if event.key == choice.key:
                event.stop()
                self.dismiss(choice.value)
                return

    @on(Button.Pressed)
    def pressed(self, event: Button.Pressed) -> None:
        self.dismiss((event.button.id or "").removeprefix("choice-") or None)

    def action_answer(self, value: str) -> None:
        self.dismiss(value or None)
