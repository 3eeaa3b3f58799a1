"""A purpose said by a second "to" straight after where someone goes (round 48): "hurries to MR2 to chair
student council", "pops to the boardroom to minute committee". The verb after the second "to" is often one
the small parser calls a noun ("chair", "minute", "host", "judge") and a bare object follows it, so neither
the verb test nor the place test of the first "to" sees a purpose there. English does not chain two
destinations with "to ... to ...", so right after a destination a "to" that opens no place's whole name
opens why they go. A place named in full ("to the lift to reception", "to gate 5") is still a place."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.particle_ends import place_end
from grove_tui.language.tokens import lemma

if TYPE_CHECKING:
    from grove_tui.language.place_phrases import Place
    from grove_tui.language.sentence import Sentence

_DESTINATIONS = frozenset({"to", "into", "towards", "toward", "obj:dest"})


def purpose_after_destination(s: Sentence, places: Sequence[Place], i: int) -> bool:
    """Whether the "to" at i, right after the clause's destination, opens a purpose (module doc)."""
    if s.low[i] != "to" or i + 2 >= s.n or not places:
        return False
    last = places[-1]
    if last.match is None or last.prep not in _DESTINATIONS or place_end(s, last) != i:
        return False
    k = i + 1
    word = s.w[k]
    if not s.low[k].isalpha() or word.pos in ("DET", "NUM", "PROPN", "ADP", "PRON") or s.low[k] in lx.DETERMINERS \
            or not word.text.islower():
        return False
    end = k
    while end < s.n and end < k + 5 and s.low[end].isalpha() and s.w[end].pos in ("NOUN", "VERB", "ADJ"):
        end += 1
    if end - k < 2:
        return False  # "to chair" alone: no object to say it is done to something
    whole = s.index.match([lemma(w) for w in s.low[k:end]])
    tail = s.index.match([lemma(w) for w in s.low[k + 1:end]])
    return not (whole is not None and whole.exact) and not (s.index.knows(lemma(s.low[k])) and tail is None)
