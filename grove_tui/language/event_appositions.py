"""A gathering that ends before the people said after it (round 32): "When the reading group finishes,
three pensioners walk to the café", "once the chess club wraps up, two students head to the desk". The
small parser takes "finishes" for a plural noun, so the people after the comma read as the gathering's
own count in apposition ("the reading group, three pensioners,"): one group named for the event. The
gathering is a time, not a group (`named_events.py`); the people after the comma are the group."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.mention import Mention
from grove_tui.language.named_events import _ENDING, _GATHERINGS, _OVER, _TIME_WORDS
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_BE = frozenset({"is", "are", "was", "were", "'s", "has", "have", "gets"})


def _ends_before(s: Sentence, m: Mention, first: int) -> bool:
    """Whether the mention is a gathering of a fronted time clause that ends at the comma before `first`."""
    last = m.last
    if s.lemma(last) not in _GATHERINGS and s.low[last] not in _GATHERINGS:
        return False
    k = m.first - 1
    while k >= 0 and s.low[k] in ("the", "this", "that", "our", "their", "his", "her", "its"):
        k -= 1
    if k < 0 or s.low[k] not in _TIME_WORDS:
        return False
    j = last + 1
    if j < s.n and s.low[j] in _BE:
        j += 1
    ending = j < s.n and (bool({verb_lemma(s.low[j]), s.lemma(j), s.w[j].lemma} & _ENDING) or s.low[j] in _OVER)
    j += 1
    while j < s.n and s.low[j] in ("up", "off", "out", "down", "for", "the", "day", "night", "session"):
        j += 1
    return ending and j == first - 1 and s.low[j] == ","


def with_people_after_an_event(s: Sentence, mentions: Sequence[Mention]) -> list[Mention]:
    """The mentions with a gathering that ends read apart from the people said after it (module doc)."""
    out: list[Mention] = []
    for m in mentions:
        a = m.apposition
        if a is not None and m.collective is not None and m.relation is None and _ends_before(s, m, a[0]):
            m = replace(m, first=a[0], last=a[1], who=s.span(a[0], a[1]), apposition=None, collective=None,
                        together=False)
        out.append(m)
    return out
