"""A bare adverb of place and then the place itself, round 34: "waits backstage in the artists'
lounge", "sits poolside at the café", "stands rinkside in the penalty box". The adverb ("backstage",
language/bare_places.py) names the area; the phrase right after it with "in" or "at" names the room
within it, where they are. Read alone, the adverb would win as the first place said, and the room
(often said by a synonym, "the artists' lounge" for the green room) would be lost."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma, phrase_lemmas

_WITHIN = frozenset({"in", "at", "inside", "into"})


def named_place_after(s: Sentence, i: int, bare: str) -> bool:
    """Whether the bare adverb of place at i (naming the world's place `bare`) is followed by "in",
    "at" or "inside" and a phrase naming another of the world's places."""
    if i + 2 >= s.n or s.low[i + 1] not in _WITHIN:
        return False
    k = s.skip(i + 2, lx.DETERMINERS)
    end = s.phrase_end(i + 2)
    words = [w for w in s.low[k:end] if w not in ("'", "’", "'s", "’s")]
    if not words or lemma(words[-1]) in lx.NON_PLACES:
        return False  # "backstage in the meantime"
    match = s.index.match(tuple(phrase_lemmas(words)))
    return match is not None and match.exact and match.name != bare and match.zone != bare
