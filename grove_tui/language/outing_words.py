"""An outing people are on is no place (round 45): "sixth-formers on a geography trip", "back from a
school outing", "pensioners on an excursion". The phrase names what they are doing, not where, so a
world without a "trip" refuses nothing."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma

# Head nouns of an outing.
OUTING_HEADS = frozenset("trip outing excursion jaunt expedition holiday honeymoon awayday away-day daytrip "
                         "day-trip fieldtrip".split())
_PREPOSITIONS = frozenset({"on", "from", "for"})


def phrase_head(s: Sentence, k: int) -> str:
    """The lemma of the last noun of the noun phrase from k ("a geography trip": trip); "" when none."""
    end = k
    while end < s.n and s.w[end].pos in ("DET", "ADJ", "NOUN", "PROPN", "NUM"):
        end += 1
    return lemma(s.low[end - 1]) if end > k else ""


def an_outing(s: Sentence, k: int, prep: str) -> bool:
    """Whether the phrase from k, after `prep`, is an outing people are on or back from."""
    return prep in _PREPOSITIONS and phrase_head(s, k) in OUTING_HEADS
