"""Counts with a tail, said inside a phrase that starts earlier (round 42): "threads through the
sixty-odd backpackers", "get the 30-odd parents in the viewing gallery out", "weaves past the twenty or so
shoppers". A group found at the tail ("odd backpackers") or at its noun ("backpackers") after a rough
count is the phrase from its number (and the determiner before it), with that count: about sixty, not a
guessed handful."""

from __future__ import annotations

from typing import Callable

from grove_tui.language.counts import number_at
from grove_tui.language.mention import Mention
from grove_tui.language.sentence import Sentence

# Words between a number and its noun that only make it rough ("twenty-odd", "thirty or so", "forty-plus").
_TAILS = frozenset("- odd or so ish plus thereabouts".split())
_BEFORE = frozenset("the these those all its their our his her my your some".split())


def _number_start(s: Sentence, end: int) -> int | None:
    """The first word of the number that ends at `end` (inclusive), else None."""
    k = end
    while k > 0 and s.w[k - 1].pos == "NUM" and not s.is_punct(k - 1):
        k -= 1
    while k <= end:
        num = number_at(s, k)
        if num is not None and num[1] == end + 1:
            return k
        k += 1
    return None


def with_counts_before(s: Sentence, mention_at: Callable[[int, list[Mention]], Mention | None],
                       found: list[Mention]) -> list[Mention]:
    """The mentions, each found after a rough count's tail widened back to the count's words."""
    for n, m in enumerate(found):
        k = m.first - 1
        tail = False
        while k > 0 and s.low[k] in _TAILS:
            tail, k = True, k - 1
        if not tail or number_at(s, k) is None or (m.count is not None and m.count.kind != "vague"):
            continue  # only a group the count was lost for ("odd backpackers": a guessed 3-6)
        start = _number_start(s, k)
        if start is None or (n > 0 and found[n - 1].last >= start):
            continue
        if start > 0 and s.low[start - 1] in _BEFORE:
            start -= 1
        wider = mention_at(start, found[:n])
        if wider is None or wider.last != m.last or wider.count is None or wider.count.kind not in ("approximate", "exact"):
            continue
        m.first, m.who, m.count = start, s.span(start, m.last), wider.count
    return found
