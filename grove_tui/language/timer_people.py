"""People called by how often or how long they have come, "-timer" (round 34): "a first-timer wanders
around the café", "two old-timers chat by the bar", "a part-timer heads to the stockroom". The parser
splits the word at its hyphen and "timer" alone is a kitchen clock, so no person was read. A "timer"
right after a hyphen and one of these words is a person."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

_TIMES = frozenset("first old part full half second third two one".split())


def timer_person(s: Sentence, i: int) -> bool:
    """Whether word i is "timer(s)" of "first-timer", "old-timer", "part-timer" (module doc)."""
    return s.low[i] in ("timer", "timers") and i >= 2 and s.low[i - 1] == "-" and s.low[i - 2] in _TIMES
