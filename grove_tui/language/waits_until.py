"""A wait that lasts until something happens, then a move (round 64b): "waits in the waiting room until
the train comes, then goes to platform 1", "sits in reception till the manager comes, then goes to the
boardroom". Like a wait for a length ("waits at the kiosk for 10 minutes, then heads to the shop"),
they set off from where they waited, though the wait has no number of seconds."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

_UNTIL = frozenset({"until", "till", "til", "untill", "'til"})


def waited_until(s: Sentence, span: tuple[int, int]) -> bool:
    """Whether the words of a group's span say how long it waits by an event ("until the doctor calls")."""
    return any(s.low[i] in _UNTIL for i in range(max(0, span[0]), min(s.n, span[1])))
