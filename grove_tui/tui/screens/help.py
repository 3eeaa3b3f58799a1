"""F1 help: what the focused widget does and every key of the current screen with its binding id."""

from __future__ import annotations

import inspect

from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.dom import DOMNode
from textual.screen import ModalScreen, Screen
from textual.widget import Widget
from textual.widgets import Markdown


def help_text(node: DOMNode | None) -> str:
    if node is None:
        return ""
    for cls in type(node).__mro__:
        text = cls.__dict__.get("HELP")
        if text:
            return inspect.cleandoc(text)
    return ""


def keys_table(screen: Screen[object]) -> str:
    """Every active binding of the screen (focused widget first), as Footer sees them."""
    rows = []
    seen: set[str] = set()
    for active in screen.active_bindings.values():
        binding = active.binding
        ident = binding.id or binding.action
        if not binding.description or ident in seen:
            continue
        seen.add(ident)
        rows.append(f"| `{screen.app.get_key_display(binding)}` | {binding.description} | `{binding.id or ''}` |")
    if not rows:
        return ""
    return "| Key | Action | Binding id |\n| :- | :- | :- |\n" + "\n".join(rows)


class HelpScreen(ModalScreen[None]):
    BINDINGS = [Binding("escape,f1,q", "dismiss", "Close", id="help.close", tooltip="Close help")]

    def __init__(self, focused: Widget | None, screen: Screen[object]) -> None:
        super().__init__()
        self._focused = focused
        self._screen = screen

    def compose(self) -> ComposeResult:
        parts = []
        widget_help = help_text(self._focused)
        screen_help = help_text(self._screen)
        if widget_help and widget_help != screen_help:
            parts.append(widget_help)
        if screen_help:
            parts.append(screen_help)
        keys = keys_table(self._screen)
        if keys:
            parts.append("## Keys\n\n" + keys)
        parts.append("**ctrl+p** opens the command palette (every action by name). Remap a key in `config.yaml` "
                     "under `keymap:` with its binding id. **Escape** closes help.")
        with Vertical(id="help-dialog"):
            yield Markdown("\n\n".join(parts), id="help-text")

    def on_mount(self) -> None:
        self.query_one("#help-text").focus()
