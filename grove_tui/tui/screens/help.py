"""F1 help: what the focused widget does and every key of the current screen with its binding id."""

from __future__ import annotations

import inspect

from rich import box
from rich.table import Table
from rich.text import Text
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical, VerticalScroll
from textual.dom import DOMNode
from textual.screen import ModalScreen, Screen
from textual.widget import Widget
from textual.widgets import Markdown, Static


def help_text(node: DOMNode | None) -> str:
    if node is None:
        return ""
    for cls in type(node).__mro__:
        text = cls.__dict__.get("HELP")
        if text:
            return inspect.cleandoc(text)
    return ""


def _identities(node: DOMNode) -> set[tuple[str, str]]:
    return {(b.id or "", b.action) for bindings in node._bindings.key_to_bindings.values()  # noqa: SLF001
            for b in bindings}


def _screen_first(screen: Screen[object]) -> list[Binding]:
    """The screen's own keys first (what the user came for), then the focused widget's, then the app's."""
    own, app_wide = _identities(screen), _identities(screen.app)

    def rank(binding: Binding) -> int:
        identity = (binding.id or "", binding.action)
        return 0 if identity in own else 2 if identity in app_wide else 1

    return sorted((entry.binding for entry in screen.active_bindings.values()), key=rank)


def key_rows(screen: Screen[object]) -> list[tuple[str, str, str]]:
    """(key, action, binding id) of every active binding of the screen, hidden ones included (screen keys first)."""
    rows = []
    seen: set[str] = set()
    for binding in _screen_first(screen):
        ident = binding.id or binding.action
        if not binding.description or ident in seen:
            continue
        seen.add(ident)
        rows.append((screen.app.get_key_display(binding), binding.description, binding.id or ""))
    return rows


def keys_table(screen: Screen[object]) -> str:
    """The keys of key_rows as a Markdown table (what the README's key lists are written from)."""
    rows = [f"| `{key}` | {action} | `{ident}` |" for key, action, ident in key_rows(screen)]
    if not rows:
        return ""
    return "| Key | Action | Binding id |\n| :- | :- | :- |\n" + "\n".join(rows)


def keys_renderable(rows: list[tuple[str, str, str]]) -> Table:
    """The keys as one Rich table: a Markdown table is a widget per cell, and styling ~60 widgets made
    F1 cost 0.3-0.6 s of the UI thread (the key response the app must keep under 100 ms)."""
    table = Table(title="Keys", title_justify="left", title_style="bold", box=box.SIMPLE_HEAD, expand=True,
                  show_edge=False, pad_edge=False)
    table.add_column("Key", style="bold", no_wrap=True)
    table.add_column("Action", ratio=1)
    table.add_column("Binding id", style="dim", overflow="fold")
    for key, action, ident in rows:
        table.add_row(key, action, ident)
    return table


class HelpScroll(VerticalScroll, can_focus=True):
    """The help page; scrolls with the usual keys plus vi's j/k and space, which also work over SSH."""

    BINDINGS = [
        Binding("j", "scroll_down", "Scroll down", show=False, id="help.down"),
        Binding("k", "scroll_up", "Scroll up", show=False, id="help.up"),
        Binding("space", "page_down", "Page down", show=False, id="help.page_down"),
    ]


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
        rows = key_rows(self._screen)
        with Vertical(id="help-dialog"), HelpScroll(id="help-scroll"):
            yield Markdown("\n\n".join(parts), id="help-text")
            if rows:
                yield Static(keys_renderable(rows), id="help-keys")
            yield Static(Text.from_markup(
                "[b]ctrl+p[/b] opens the command palette (every action by name). Remap a key in "
                "[i]config.yaml[/i] under [i]keymap:[/i] with its binding id. [b]Escape[/b] closes help."),
                id="help-footer")

    def on_mount(self) -> None:
        self.query_one("#help-scroll").focus()
