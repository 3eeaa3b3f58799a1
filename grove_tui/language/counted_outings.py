"""A bare count said by the outing or party the people are on (round 44): "About twenty on the brewery
tour form a line at the tasting bar", "Thirty on the guided tour walk to the café", "a dozen from the
stag party wait in the tap room". The count names no kind of people, so the outing's collective noun
("tour", "party") was read as a second group and took the clause, or nobody was found. The count is of
people on the outing: written as "twenty people on the brewery tour" before parsing, one group."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx

_NUMBER = r"(?:\d+|" + "|".join(sorted((w for w in lx.NUMBER_WORDS if w.isalpha() and w not in
                                        ("couple", "pair", "handful", "dozens", "one", "a")), key=len, reverse=True)) + \
    r")(?:-(?:one|two|three|four|five|six|seven|eight|nine))?"
_APPROXIMATE = r"(?:(?:about|around|some|roughly|nearly|almost|maybe|perhaps|over|under|approximately|a|another)\s+)?"
# Outings, visits and parties people go on or come from.
_OUTINGS = ("tour|tours|trip|trips|outing|excursion|visit|course|class|session|workshop|lesson|party|walk|ride|"
            "coach|bus|flight|cruise|crossing|tasting|expedition|minibus|train|ferry|boat|hen|stag|do")
_COUNTED_OUTING = re.compile(r"(^|[,;:.!?]\s*|\b(?:and|while|as|then|but|when)\s+)(" + _APPROXIMATE + _NUMBER +
                             r"(?:\s+or\s+so|-odd)?)(\s+(?:on|from|off)\s+(?:the|a|an|our|their|this|that)\s+"
                             r"(?:[\w'’-]+\s+){0,3}(?:" + _OUTINGS + r")\b)", re.IGNORECASE)


def with_counted_outings(text: str) -> str:
    """The text with a bare count on an outing said as so many people (module doc)."""
    return _COUNTED_OUTING.sub(lambda m: f"{m.group(1)}{m.group(2)} people{m.group(3)}", text)
