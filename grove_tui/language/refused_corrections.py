"""A spelling correction that turns a real English word into another is taken back when the place it
makes is refused anyway (round 48): "from the car park" in a world with luggage carts and no car park
read "car" as a shortening of "cart" and refused "cart park". The world lacks the place either way, so
the refusal names it as the researcher wrote it ("car park"), and nothing else of the sentence changes
for a word that was spelt right."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.parser import Word, known_word
from grove_tui.language.places import PlaceIndex
from grove_tui.language.spelling import correction_of
from grove_tui.language.text import plain


def refused_real_words(words: Sequence[Word], index: PlaceIndex, unknown: Sequence[str]) -> frozenset[int]:
    """The indices of the real words whose correction ends in a refused place (module doc)."""
    refused = {w for phrase in unknown for w in phrase.lower().split()}
    if not refused:
        return frozenset()
    taken: set[int] = set()
    for k, w in enumerate(words):
        low = plain(w.lower)
        if not low.isalpha() or not known_word(low):
            continue
        replacement = (correction_of(words, k, index) or "").lower().split()
        if replacement and all(r in refused for r in replacement):
            taken.add(k)
    return frozenset(taken)
