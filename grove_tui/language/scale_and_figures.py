"""A scale word with its tail after "and" as one number (round 60): "the hundred and twenty or so
agents", "two hundred and fifty fans", "a hundred and five guests". The clause splitter and the
count reader took the "and" as joining two things, so only the tail was counted ("twenty or so
agents"). Written before parsing as its figure ("the 120 or so agents", "250 fans"), the number
reads whole; "a"/"an" before the scale goes with it ("a hundred and twenty": 120)."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx

_UNIT = "|".join(sorted(lx.UNITS, key=len, reverse=True))
_TEN = "|".join(lx.TENS)
_LEAD = r"a|an|the|some|another|these|those|" + _UNIT
_SCALE = re.compile(rf"\b(?:({_LEAD})\s+)(hundred|thousand)\s+and\s+(?:({_TEN})(?:\s*-\s*|\s+)({_UNIT})\b|({_TEN}|{_UNIT})\b)",
                    re.IGNORECASE)
_KEPT = frozenset("the some another these those".split())


def _figure(m: re.Match[str]) -> str:
    lead, scale = m.group(1), m.group(2).lower()
    low = lead.lower()
    times = lx.UNITS.get(low, 1)
    if times == 0:
        return m.group(0)
    tail_words = [x.lower() for x in (m.group(3), m.group(4), m.group(5)) if x]
    if len(tail_words) == 2 and lx.UNITS[tail_words[1]] >= 10:
        return m.group(0)  # "twenty ten": no number
    tail = sum(lx.UNITS.get(x, lx.TENS.get(x, 0)) for x in tail_words)
    figure = str(times * lx.SCALES[scale] + tail)
    return f"{lead} {figure}" if low in _KEPT else figure


def with_scale_and_figures(text: str) -> str:
    """The text with "(a|the|two) hundred and twenty" written as its figure (module doc)."""
    return _SCALE.sub(_figure, text)
