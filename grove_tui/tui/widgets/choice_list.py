"""An option list that passes typing on to a text field: picking a world and going on typing the sentence
never loses a letter.

Enter in the list moves the focus back to the prompt, but keys typed right after it reach the list first
(the terminal delivers them before the focus moves, more so on a loaded machine): they used to vanish.
The lists bind no printable key, so every printable key they get belongs to the text field.
"""

from __future__ import annotations

from textual import events
from textual.widgets import OptionList, TextArea


class ChoiceList(OptionList):
    def __init__(self, *, typing_target: str, id: str | None = None) -> None:
        super().__init__(id=id)
        self.typing_target = typing_target  # the id of the TextArea that gets the list's typing

    async def _on_key(self, event: events.Key) -> None:
        if event.is_printable and event.character:
            field = self.screen.query_one(f"#{self.typing_target}", TextArea)
            if not field.read_only:
                event.stop()
                event.prevent_default()
                if self.screen.focused is not field:  # the first key typed here: to the end of the sentence
                    self.screen.set_focus(field)
                    field.move_cursor(field.document.end)
                field.insert(event.character)
                return
        await super()._on_key(event)
