"""A time said by a fronted phrase with no comma after it (round 44): "During the Saturday changeover a
bellboy wheels a stack of suitcases to the lifts, ...", "After the lunchtime rush two waiters lay the
tables", "Before the doors open the stewards take their places". The parser runs the time's noun into the
people after it ("changeover a bellboy"), so the first group is lost. A comma after the time keeps them
apart, as the writer would have put one; it is written so. Only "during", "after", "before", "following"
and "throughout" with a determiner open such a time, and only a determiner, a count or a name after it
closes it ("After the lecture theatre empties, ..." is a clause, and keeps its own words)."""

from __future__ import annotations

import re

_OPENS = r"(?:During|After|Before|Following|Throughout|Until|Till)"
_DETERMINERS = r"(?:the|a|an|this|that|his|her|their|our|its|my|your)"
_CLOSERS = ("a an the two three four five six seven eight nine ten eleven twelve twenty thirty forty fifty some "
            "several both all every each most many few our their his her my your").split()
_NOT_IN_TIME = set(_CLOSERS) | {"is", "are", "was", "were", "and", "or", "but", "to", "in", "at", "on", "of", "with"}
_WORD = r"[A-Za-z][A-Za-z'-]*"
_FRONTED = re.compile(
    rf"(^|[.!?;]\s+)({_OPENS}\s+{_DETERMINERS}\s+(?P<words>{_WORD}(?:\s+{_WORD}){{0,3}}?))"
    rf"(?=\s+(?:(?:{'|'.join(_CLOSERS)})\b|\d|(?:Mr|Mrs|Ms|Dr|Miss)\b))")


def with_fronted_time_commas(text: str) -> str:
    """The text with a comma after a fronted time that runs into the people after it (module doc)."""
    def comma(m: re.Match[str]) -> str:
        words = m.group("words").lower().split()
        if any(w in _NOT_IN_TIME for w in words):
            return m.group(0)
        return f"{m.group(1)}{m.group(2)},"
    return _FRONTED.sub(comma, text)
