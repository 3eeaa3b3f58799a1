"""Text fields that keep readline's keys, and the prompt box: a sentence on as many lines as it needs.

Shell and editor users press ctrl+w to delete a word hundreds of times a day: every text field of the
app keeps readline's editing keys (ctrl+w and alt+backspace, which terminals send as ctrl+w, delete
the word before the cursor; ctrl+u to the start, ctrl+k to the end; ctrl+a / ctrl+e go to the
start / end; alt+b / alt+f move by word), and no screen binds them to anything else.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from textual import events
from textual.binding import Binding
from textual.message import Message
from textual.widgets import Input, TextArea

READLINE_HELP = """\
**Editing** as in a shell: **ctrl+w** (or alt+backspace) deletes the word before the cursor,
**ctrl+u** everything before it, **ctrl+k** everything after it; **ctrl+a** / **ctrl+e** go to the
start / end, **alt+b** / **alt+f** move by word."""
LINE_BREAKS = re.compile(r"\s*[\r\n]+\s*")


class ReadlineInput(Input):
    """A one-line field (the seed, the head counts) with readline's keys.

    Textual's Input binds alt+backspace and ctrl+backspace to deleting the word *after* the cursor;
    every shell deletes the one before it.
    """

    BINDINGS = [
        Binding("ctrl+backspace,alt+backspace", "delete_left_word", "Delete the word before the cursor",
                show=False, id="input.delete_word"),
        Binding("alt+b", "cursor_left_word", "Word left", show=False, id="input.word_left"),
        Binding("alt+f", "cursor_right_word", "Word right", show=False, id="input.word_right"),
        Binding("alt+d", "delete_right_word", "Delete the word after the cursor", show=False,
                id="input.delete_word_right"),
    ]


class PromptInput(TextArea):
    """The sentence: wraps onto as many lines as it needs (the CSS caps how many show), Enter submits,
    Up on the first line and Down on the last walk through earlier prompts, readline keys edit it.

    One paragraph only: Enter submits instead of breaking the line, and a pasted line break becomes a
    space, so what the box shows is the sentence the model gets.
    """

    HELP = f"""\
## Prompt

Describe the crowd in one sentence, e.g. *"ten patients queue at the pharmacy while a robot
crosses the hall"*. **Enter** generates. The box grows to show the whole sentence; **Up** on its
first line and **Down** on its last walk through earlier prompts.

{READLINE_HELP}
"""

    BINDINGS = [
        Binding("ctrl+a", "text_start", "Start of the prompt", show=False, id="prompt.start"),
        Binding("ctrl+e", "text_end", "End of the prompt", show=False, id="prompt.end"),
        Binding("ctrl+u", "delete_to_text_start", "Delete to the start", show=False, id="prompt.delete_to_start"),
        Binding("ctrl+k", "delete_to_text_end", "Delete to the end", show=False, id="prompt.delete_to_end"),
        # alt+backspace reaches the app as ctrl+w (terminals send ESC DEL); TextArea's own binding also
        # keeps ctrl+backspace for terminals that report it.
        Binding("ctrl+w", "delete_word_left", "Delete the word before the cursor", show=False,
                id="prompt.delete_word"),
        Binding("alt+b", "cursor_word_left", "Word left", show=False, id="prompt.word_left"),
        Binding("alt+f", "cursor_word_right", "Word right", show=False, id="prompt.word_right"),
        Binding("alt+d", "delete_word_right", "Delete the word after the cursor", show=False,
                id="prompt.delete_word_right"),
    ]

    @dataclass
    class Submitted(Message):
        """Enter in the prompt box."""

        prompt: PromptInput
        value: str

        @property
        def control(self) -> PromptInput:
            return self.prompt

    def __init__(self, history: list[str] | None = None, *, placeholder: str = "", id: str | None = None) -> None:
        super().__init__("", id=id, soft_wrap=True, show_line_numbers=False, tab_behavior="focus",
                         highlight_cursor_line=False, placeholder=placeholder)
        self.prompt_history = history if history is not None else []
        self._history_index: int | None = None
        self._draft = ""

    # the text as one value -------------------------------------------------------------------------
    @property
    def value(self) -> str:
        return self.text

    @value.setter
    def value(self, text: str) -> None:
        self.text = LINE_BREAKS.sub(" ", text)
        self.action_text_end()

    @property
    def end_location(self) -> tuple[int, int]:
        return self.document.end

    def action_text_start(self) -> None:
        self.move_cursor((0, 0))

    def action_text_end(self) -> None:
        self.move_cursor(self.document.end)

    def action_delete_to_text_start(self) -> None:
        if not self.read_only:
            self.delete((0, 0), self.selection.end)

    def action_delete_to_text_end(self) -> None:
        if not self.read_only:
            self.delete(self.selection.start, self.document.end)

    # keys ------------------------------------------------------------------------------------------
    async def _on_key(self, event: events.Key) -> None:
        if event.key == "enter":
            event.stop()
            event.prevent_default()
            self.post_message(self.Submitted(self, self.text))
            return
        await super()._on_key(event)

    async def _on_paste(self, event: events.Paste) -> None:
        """A pasted line break becomes a space: the prompt is one sentence on one line."""
        event.stop()
        event.prevent_default()
        if self.read_only:
            return
        if result := self._replace_via_keyboard(LINE_BREAKS.sub(" ", event.text), *self.selection):
            self.move_cursor(result.end_location)
            self.focus()

    def action_cursor_up(self, select: bool = False) -> None:
        if not select and self.navigator.is_first_wrapped_line(self.cursor_location):
            self.action_history(-1)
        else:
            super().action_cursor_up(select)

    def action_cursor_down(self, select: bool = False) -> None:
        if not select and self.navigator.is_last_wrapped_line(self.cursor_location):
            self.action_history(1)
        else:
            super().action_cursor_down(select)

    # history ---------------------------------------------------------------------------------------
    def action_history(self, step: int) -> None:
        if not self.prompt_history:
            return
        if self._history_index is None:
            if step > 0:
                return
            self._draft = self.text
            index = len(self.prompt_history) - 1
        else:
            index = self._history_index + step
        if index >= len(self.prompt_history):
            self._history_index = None
            self.value = self._draft
        else:
            self._history_index = max(0, index)
            self.value = self.prompt_history[self._history_index]

    def reset_history_position(self) -> None:
        self._history_index = None
