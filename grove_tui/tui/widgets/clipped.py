"""Text that says when it was cut: wrapped to the widget's width, and where it has more lines than
the widget shows, the last one shown ends with "…"."""

from __future__ import annotations

import textwrap

from textual.geometry import Size
from textual.widget import Widget


def clip_lines(text: str, width: int, lines: int) -> list[str]:
    """`text` wrapped to `width`, at most `lines` lines; the last ends with "…" when text is left out."""
    width = max(1, width)
    wrapped = [line for paragraph in text.splitlines() for line in (textwrap.wrap(paragraph, width) or [""])]
    if len(wrapped) <= lines:
        return wrapped
    if lines <= 0:
        return []
    kept = wrapped[:lines]
    last = kept[-1]
    kept[-1] = (last if len(last) < width else last[: width - 1].rstrip()) + "…"
    return kept


class ClippedText(Widget):
    """Plain text over at most `max_lines` lines (fewer when the layout gives it fewer), cut with "…"."""

    DEFAULT_CSS = """
    ClippedText { height: auto; }
    """

    def __init__(self, text: str = "", *, max_lines: int = 3, id: str | None = None,
                 classes: str | None = None) -> None:
        super().__init__(id=id, classes=classes)
        self.text = text
        self.max_lines = max_lines

    def update(self, text: str) -> None:
        self.text = text
        self.refresh(layout=True)

    def get_content_height(self, container: Size, viewport: Size, width: int) -> int:
        return len(clip_lines(self.text, width, self.max_lines))

    def render(self) -> str:
        size = self.content_size
        return "\n".join(clip_lines(self.text, size.width, min(self.max_lines, size.height)))
