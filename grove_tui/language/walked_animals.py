"""Walking an animal in a place (twenty-second session): "two volunteers walking dogs in the paddock", "a
man walks his dog round the lake shore", "2 more walkin dogs in paddock". Walking with an animal as its
object is an activity kept inside the place, not a walk that sets off from it: with no place to go to,
the people wander there."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading

_WALKED = re.compile(r"\bwalk(?:s|ed|ing|in'?)?\s+(?:(?:the|a|an|his|her|their|our|my|two|three|some|)\s*)"
                     r"(?:[a-z-]+\s+)?(?:dogs?|pupp(?:y|ies)|pups?|ponies|pony|horses?|goats?|llamas?|alpacas?)\s+"
                     r"(?:in|round|around|on|about|across)\b", re.I)


def walked_animals(groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """Groups read as walking from a place with nowhere to go, whose words walk an animal there, wander there."""
    out: list[GroupReading] = []
    for g in groups:
        if g.intent == "walk" and g.destination is None and g.start is not None and _WALKED.search(g.text):
            g = replace(g, intent="wander", location=g.start, start=None)
        out.append(g)
    return tuple(out)
