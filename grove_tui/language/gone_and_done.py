"""Going and doing something in a place is going there (round 53): "three nine-year-olds go and flop
in the café seating", "two dads went and sat in the family room", "the twins go and hide behind the
stage". "Go and <verb> in X" says where the people go, though the second verb (a stay) would read X
as where they already are. The reader knows "go to X" well, so the phrase is said that way before the
sentence is read, in the going verb's own form ("went and sat in the" -> "went to the"). A wait or a
queue ("go and queue at the bar") is left as it is: the reader reads that stay where it is said."""

from __future__ import annotations

import re

_GONE_AND = re.compile(
    r"\b(?P<go>go|goes|went|going|gone)\s+and\s+(?P<verb>[a-z]+)(?:\s+(?:down|about|around|round|up|off))?"
    r"\s+(?:in|on|at|by|inside|near|beside|behind)\s+(?=(?:the|a|an|their|our|his|her|its|this|that|one)\b)",
    re.IGNORECASE)
_STAYS_SAID = frozenset("wait waits waited waiting queue queues queued queueing queuing line lines lined".split())


def as_gone_to(text: str) -> str:
    """The text with going and doing something in a place said as going to it (module doc)."""
    def say(m: re.Match[str]) -> str:
        if m.group("verb").lower() in _STAYS_SAID:
            return m.group(0)
        return f"{m.group('go')} to "
    return _GONE_AND.sub(say, text)
