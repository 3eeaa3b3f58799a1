"""A scale word said roughly with "a" ("a dozen or so club members", "a score or so guests", "a
hundred or so fans") is about that many: written before parsing as the number ("twelve or so"), which
the counts read as approximate. Without this "a dozen or" was begun as a range ("a dozen or two")
that never came, and the count fell back to a vague few."""

from __future__ import annotations

import re

_SCALES = {"dozen": "twelve", "score": "twenty"}
_ROUGH = re.compile(r"(?<!half\s)\b(a|about\s+a|some)\s+(dozen|score)\s+or\s+so\b", re.IGNORECASE)


def _number(m: re.Match[str]) -> str:
    lead = m.group(1)
    about = "about " if lead.lower().startswith("about") else ""
    word = _SCALES[m.group(2).lower()]
    if lead[:1].isupper():
        return f"{about.capitalize()}{word}" + " or so" if about else f"{word.capitalize()} or so"
    return f"{about}{word} or so"


def with_rough_scales(text: str) -> str:
    """The text with "a dozen or so" (not "half a dozen or so") and "a score or so" written as "twelve or so", "twenty or so"."""
    return _ROUGH.sub(_number, text)
