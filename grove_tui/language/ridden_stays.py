"""A place ridden or swum for a while (round 63): "a BMXer rides the street course for twenty minutes, then
heads off to ...", "two girls skate the bowl for an hour", "a man swims the lap pool for half an hour".
A verb of riding, skating or swimming with the place as its object and a span of time right after it says
where they spend that time: the place is where they are (so where they start when they go on). Without the
span ("rides the lift to level 2", "rides the bus") the object stays what it was."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

RIDING_VERBS = frozenset("ride skate swim surf cycle bike board blade rollerblade scoot paddle row".split())
_SPAN_WORDS = frozenset("minute minutes min mins hour hours hr hrs while bit ages spell second seconds "
                        "morning afternoon evening session".split())
_WITHIN = 5  # words from "for" to the word of time


def ridden_for_a_while(s: Sentence, verb: str, obj: int) -> bool:
    """The object at obj of a riding verb is followed by a span of time ("for twenty minutes")."""
    if verb not in RIDING_VERBS or obj >= s.n:
        return False
    end = s.phrase_end(obj)
    if end >= s.n or s.low[end] != "for":
        return False
    return any(s.low[j] in _SPAN_WORDS for j in range(end + 1, min(s.n, end + 1 + _WITHIN)))
