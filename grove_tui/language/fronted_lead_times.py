"""A lead time said before a fronted "ahead of", "before", "after" or "in advance of" (round 60): "Ten
minutes ahead of the late shift, the six recruits file out ...", "Twenty minutes before the night crew
clocks on, two cleaners ...". The count of the duration ("ten") was taken for a count of the people
the phrase names ("the late shift": ten of them), and a crew or shift said in a time phrase became a
group. The lead time says only when: it is dropped before parsing, and the fronted phrase reads as
"Ahead of the late shift, ..." does (a time, its people no group)."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx

_NUMBER = "|".join(sorted((w for w in lx.UNITS | lx.TENS), key=len, reverse=True))
_LEAD = re.compile(rf"(^|[.!?;]\s+)(?:(?:a|an|one|a\s+few|a\s+couple\s+of|half\s+an|\d+|{_NUMBER})(?:\s*-\s*odd)?\s+)"
                   r"(?:minutes?|mins?|hours?|hrs?|seconds?|secs?)\s+(ahead\s+of|before|after|in\s+advance\s+of)\b",
                   re.IGNORECASE)


def without_fronted_lead_times(text: str) -> str:
    """The text with a lead time before a fronted "ahead of"/"before"/"after" dropped (module doc)."""
    def cut(m: re.Match[str]) -> str:
        said = m.group(2)
        return m.group(1) + said[:1].upper() + said[1:]
    return _LEAD.sub(cut, text)
