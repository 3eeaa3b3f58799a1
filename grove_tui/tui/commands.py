"""Command palette entries (ctrl+p): the main actions of whichever screen is active.

Screens list their actions with `command_entries()` yielding (title, help, callback), so the palette
always offers what the screen can do right now.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from functools import partial
from typing import TYPE_CHECKING, cast

from textual.command import DiscoveryHit, Hit, Hits, Provider

if TYPE_CHECKING:
    from grove_tui.tui.app import GroveApp

CommandEntry = tuple[str, str, Callable[[], object]]


def screen_entries(screen: object) -> list[CommandEntry]:
    entries = getattr(screen, "command_entries", None)
    if entries is None:
        return []
    return list(entries())


class GroveCommands(Provider):
    def _entries(self) -> Iterable[CommandEntry]:
        yield from screen_entries(self.screen)
        app = cast("GroveApp", self.app)  # the provider of GroveApp.COMMANDS, in that app only
        yield ("Help", "Help for the focused widget and the keys of this screen", app.action_help)

    async def discover(self) -> Hits:
        for title, help_text, callback in self._entries():
            yield DiscoveryHit(title, partial(callback), help=help_text)

    async def search(self, query: str) -> Hits:
        matcher = self.matcher(query)
        for title, help_text, callback in self._entries():
            score = matcher.match(title)
            if score > 0:
                yield Hit(score, matcher.highlight(title), partial(callback), help=help_text)
