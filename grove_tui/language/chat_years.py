"""Years typed as chat (round 59), written out before the prompt is parsed: "12 yr 6 kids at the T. rex"
(a school year, counted: "yr" read as "year" only before the year's figure, since chat's "yr" is also
"your"), and "4 first yrs in the common room" (students by their year of study, counted: "first-years",
which `text.normalise` then reads as first-year students). "5 yrs" after a count is years."""

from __future__ import annotations

import re

from grove_tui.language.lexicon import NUMBER_WORDS

# "yr 6", "yr6", "yrs 10 and 11": a school year by its figure.
_YEAR_FIGURE = re.compile(r"\b(yr)(s?)\s?(?=(?:1[0-3]|[1-9])\b)", re.IGNORECASE)
_COUNT = r"(?:\d+|" + "|".join(sorted((w for w in NUMBER_WORDS if w.isalpha()), key=len, reverse=True)) + r")"
# "4 first yrs", "three final years": a count of students by their year of study.
_YEAR_OF_STUDY = re.compile(r"\b(" + _COUNT + r")\s+(first|second|third|fourth|final|1st|2nd|3rd|4th)\s+(?:yrs|years)\b"
                            r"(?![- ](?:old|ago|later|on|before|after|of)\b)", re.IGNORECASE)
# "5 yrs", "2 yrs old": years after a count.
_COUNTED_YRS = re.compile(r"(?<=\d)(\s*)yrs?\b", re.IGNORECASE)


def chat_years(text: str) -> str:
    """The text with chat's years written out (see the module doc)."""
    text = _YEAR_FIGURE.sub(lambda m: f"year{m.group(2)} ", text)
    text = _YEAR_OF_STUDY.sub(lambda m: f"{m.group(1)} {m.group(2)}-years", text)
    return _COUNTED_YRS.sub(lambda m: f"{m.group(1)}year{'s' if m.group(0).lower().endswith('s') else ''}", text)
