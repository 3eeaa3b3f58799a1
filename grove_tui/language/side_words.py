"""A team's side said before its people (round 27): "five hundred away fans", "twenty away
supporters", "the away players". The parser takes "away" for an adverb of the count before it
("three away" as a distance), but before a word for people it says whose side they are on, like
"home fans": a modifier of the people, inside their phrase."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

_SIDES = frozenset({"away"})


def side_word(s: Sentence, k: int) -> bool:
    """Whether word k is "away" said of the people after it ("away fans")."""
    return s.low[k] in _SIDES and k > 0 and k + 1 < s.n and s.w[k + 1].pos in ("NOUN", "PROPN") and \
        s.w[k + 1].tag in ("NNS", "NNPS", "NN") and s.low[k - 1] not in ("go", "goes", "went", "walk", "walks", "run")
