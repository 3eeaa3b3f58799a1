"""F1 help: what the focused widget does and every key of the current screen with its binding id."""

from __future__ import annotations

import inspect

from rich import box
from rich.console import Group, RenderableType
from rich.markdown import Markdown
from rich.style import Style
from rich.table import Table
from rich.text import Text
from rich.theme import Theme
from textual.app import ComposeResult
from textual.binding import Binding
from textual.cache import LRUCache
from textual.containers import Vertical
from textual.dom import DOMNode
from textual.geometry import Size
from textual.screen import ModalScreen, Screen
from textual.scroll_view import ScrollView
from textual.strip import Strip
from textual.widget import Widget

FOOTER = ("[b]ctrl+p[/b] opens the command palette (every action by name). Remap a key in "
          "[i]config.yaml[/i] under [i]keymap:[/i] with its binding id. [b]Escape[/b] closes help.")


def help_text(node: DOMNode | None) -> str:
    if node is None:
        return ""
    for cls in type(node).__mro__:
        text = cls.__dict__.get("HELP")
        if text:
            return inspect.cleandoc(text)
    return ""


def help_markdown(focused: DOMNode | None, screen: DOMNode) -> str:
    """The page's prose: the focused widget's help (when it has its own), then the screen's. A text field's
    help always says its editing keys (every field keeps readline's; the keys table names only one key of
    each binding: not alt+backspace, nor ctrl+a beside home)."""
    from textual.widgets import Input, TextArea

    from grove_tui.tui.widgets.prompt_input import READLINE_HELP

    parts = []
    widget_help = help_text(focused)
    screen_help = help_text(screen)
    if widget_help and widget_help != screen_help:
        parts.append(widget_help)
    editable = isinstance(focused, Input) or (isinstance(focused, TextArea) and not focused.read_only)
    if editable and READLINE_HELP not in widget_help:
        parts.append(READLINE_HELP)
    if screen_help:
        parts.append(screen_help)
    return "\n\n".join(parts)


def _identities(node: DOMNode) -> set[tuple[str, str]]:
    return {(b.id or "", b.action) for bindings in node._bindings.key_to_bindings.values()  # noqa: SLF001
            for b in bindings}


def _screen_first(screen: Screen[object]) -> list[Binding]:
    """The screen's own keys first (what the user came for), then the focused widget's, then the app's."""
    own, app_wide = _identities(screen), _identities(screen.app)

    def rank(binding: Binding) -> int:
        identity = (binding.id or "", binding.action)
        if identity in own:
            return 0 if binding.id else 1  # the screen's own keys, then Textual's (tab: focus next)
        return 3 if identity in app_wide else 2

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


PageKey = tuple[str, tuple[tuple[str, str, str], ...], int, tuple[Style, ...]]
# Rendered pages by (prose, keys, width, styles): a screen's help is the same page every time F1 is
# pressed there, so the second and later presses only crop lines (the cache is small: a page is a
# few dozen strips, and there are about ten screens and dialogs).
_PAGES: LRUCache[PageKey, list[Strip]] = LRUCache(32)


class HelpPage(ScrollView, can_focus=True):
    """The help page as lines rendered once per width and reused (Line API), scrolled by keyboard.

    It used to be a Markdown widget (a widget per block, each styled and laid out) and a Rich table
    in a Static, rendered twice per open (height, then lines): 60-200 ms of the UI thread per F1 at
    120x40. Here the prose, the keys table and the footer are rendered to strips in one pass, kept in
    `_PAGES`, and each visible line is a crop of a cached strip. The usual scroll keys work, plus
    vi's j/k and space, which also work over SSH.
    """

    BINDINGS = [
        Binding("j", "scroll_down", "Scroll down", show=False, id="help.down"),
        Binding("k", "scroll_up", "Scroll up", show=False, id="help.up"),
        Binding("space", "page_down", "Page down", show=False, id="help.page_down"),
    ]
    COMPONENT_CLASSES = {"help--heading", "help--code", "help--strong", "help--bullet", "help--key", "help--dim"}
    DEFAULT_CSS = """
    HelpPage { scrollbar-gutter: stable; }
    HelpPage > .help--heading { color: $markdown-h2-color; text-style: $markdown-h2-text-style; }
    HelpPage > .help--code { color: $text-warning 95%; background: $warning 10%; }
    HelpPage > .help--strong { text-style: bold; }
    HelpPage > .help--bullet { color: $text-primary; }
    HelpPage > .help--key { text-style: bold; }
    HelpPage > .help--dim { text-style: dim; }
    """

    def __init__(self, markdown: str, rows: list[tuple[str, str, str]], *, id: str | None = None) -> None:
        super().__init__(id=id)
        self.markdown = markdown
        self.rows = tuple(rows)
        self._strips: list[Strip] = []
        self._width = -1

    def notify_style_update(self) -> None:
        super().notify_style_update()
        self._width = -1  # the theme changed: look the page up again under the new styles

    def _styles(self) -> tuple[Style, ...]:
        return (self.rich_style, *(self.get_component_rich_style(name, partial=True) for name in (
            "help--heading", "help--code", "help--strong", "help--bullet", "help--key", "help--dim")))

    def page(self, width: int) -> list[Strip]:
        """The page's lines at `width` columns, rendered once and then taken from the cache."""
        styles = self._styles()
        key = (self.markdown, self.rows, width, styles)
        strips = _PAGES.get(key)
        if strips is None:
            strips = self._render_page(width, styles)
            _PAGES[key] = strips
        return strips

    def _render_page(self, width: int, styles: tuple[Style, ...]) -> list[Strip]:
        base, heading, code, strong, bullet, key, dim = styles
        theme = Theme({
            "markdown.h1": heading, "markdown.h2": heading, "markdown.h3": heading + strong,
            "markdown.code": code, "markdown.strong": strong, "markdown.item.bullet": bullet,
            "markdown.em": Style(italic=True), "markdown.paragraph": Style(), "markdown.text": Style(),
        })
        parts: list[RenderableType] = []
        if self.markdown:
            parts.extend([Markdown(self.markdown, hyperlinks=False), Text("")])
        if self.rows:
            table = keys_renderable(list(self.rows))
            table.title_style = strong
            table.columns[0].style = key
            table.columns[2].style = dim
            parts.extend([table, Text("")])
        parts.append(Text.from_markup(FOOTER))
        console = self.app.console
        with console.use_theme(theme):
            lines = console.render_lines(Group(*parts), console.options.update(width=width, height=None),
                                         style=base, pad=True)
        return [Strip(line, width) for line in lines]

    def _ensure_page(self) -> None:
        width = self.scrollable_content_region.width
        if width <= 0 or width == self._width:
            return
        self._width = width
        self._strips = self.page(width)
        self.virtual_size = Size(width, len(self._strips))

    def on_resize(self) -> None:
        self._ensure_page()

    def plain_text(self) -> str:
        """The page as text at its current width (what the tests read)."""
        self._ensure_page()
        return "\n".join(strip.text.rstrip() for strip in self._strips)

    def render_line(self, y: int) -> Strip:
        # Built here on the first paint too, so F1 paints the page at once rather than an empty frame
        # before the resize event arrives.
        self._ensure_page()
        scroll_x, scroll_y = self.scroll_offset
        row = scroll_y + y
        width = self.scrollable_content_region.width
        if row >= len(self._strips):
            return Strip.blank(width, self.rich_style)
        return self._strips[row].crop_extend(scroll_x, scroll_x + width, self.rich_style)


class HelpScreen(ModalScreen[None]):
    BINDINGS = [Binding("escape,f1,q", "dismiss", "Close", id="help.close", tooltip="Close help")]

    def __init__(self, focused: Widget | None, screen: Screen[object]) -> None:
        super().__init__()
        self._focused = focused
        self._screen = screen

    def compose(self) -> ComposeResult:
        with Vertical(id="help-dialog"):
            yield HelpPage(help_markdown(self._focused, self._screen), key_rows(self._screen), id="help-scroll")

    def on_mount(self) -> None:
        self.query_one("#help-scroll").focus()
