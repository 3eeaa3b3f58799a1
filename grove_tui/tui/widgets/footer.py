"""Textual's Footer without its leak: every recompose used to keep the previous keys alive."""

from __future__ import annotations

from textual.app import ComposeResult
from textual.widgets import Footer as TextualFooter


class Footer(TextualFooter):
    """The key footer; drops the watchers of keys it has removed before composing new ones.

    Textual's Footer binds each FooterKey's `compact` to its own with `data_bind`, which registers a
    watcher on the footer that is pruned only when `compact` changes, and ours never does. The footer
    recomposes on every bindings change (focus moves, screens open and close), so each F1/Escape
    left ~20 dead keys with their cached strips (~7,000 objects) reachable from the footer: the
    heap grew for the whole session and every full garbage collection, which pauses the UI thread,
    took longer (issue 21: key response).
    """

    def compose(self) -> ComposeResult:
        self.forget_removed_keys()
        yield from super().compose()

    def forget_removed_keys(self) -> int:
        """Drop watchers whose widget was removed; returns how many were dropped."""
        watchers = getattr(self, "__watchers", {}).get("compact")
        if not watchers:
            return 0
        kept = [(node, callback) for node, callback in watchers
                if not (getattr(node, "_closing", False) or getattr(node, "_closed", False))]
        dropped = len(watchers) - len(kept)
        watchers[:] = kept
        return dropped
