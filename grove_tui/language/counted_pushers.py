"""Counted people who push, wheel or drag things ("a pair of bellboys wheel luggage trolleys", "a
couple of mums wheel prams"): after a count, the word after the plural person noun is their verb,
though the parser makes it a noun of a compound with the things they move."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language.counts import quantifier

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

# Verbs of moving a thing along by hand that the parser reads as nouns before the thing ("wheel
# prams", "push carts", "drag cases").
_HAND_VERBS = frozenset("wheel push drag pull tow trundle cart lug haul roll steer".split())


def counted_at(s: Sentence, k: int) -> bool:
    """Whether a count ends right before word k ("two", "a pair of", "a couple of", "half a dozen")."""
    for i in range(max(0, k - 4), k):
        q = quantifier(s, i)
        if q is not None and q.end == k:
            return True
    return False


def pushes_after(s: Sentence, k: int) -> bool:
    """Whether the counted plural person noun at k is followed by a verb of moving a thing by hand
    ("a pair of porters wheel trolleys"), which the person noun does not modify."""
    return (k + 2 < s.n and s.low[k + 1] in _HAND_VERBS and s.lemma(k) != s.low[k]
            and s.w[k + 2].pos in ("NOUN", "DET", "PRON") and counted_at(s, k))
