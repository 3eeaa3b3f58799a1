"""A person named after "and" in a placing order (round 56): "Put three visitors in the canteen and Tom at
reception", "Have two teenagers on the settee and Dad at the cooker". `placed_people.py` reads the
placing verb's own object; the parser hangs a name or a kin word after "and" on the verb or on the
first item's place instead, so it was no one. In a sentence that opens with a placing verb, a
capitalised name or a kin word right after "and", with a place preposition after it and a place of the
world close behind, is one more person placed."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

_PLACING = frozenset({"put", "place", "position", "sit", "seat", "stick", "plant", "station", "post", "pop", "have"})
_WHERE = frozenset("on at in by near beside behind inside outside next".split())


def placed_after_and(s: Sentence, i: int) -> bool:
    """Whether word i is a name or a kin word placed after "and" in a placing order (module doc)."""
    if i < 2 or s.low[i - 1] != "and" or i + 2 >= s.n or s.low[i + 1] not in _WHERE:
        return False
    text = s.w[i].text
    if not (s.low[i] in lx.KIN_NAMES or (s.w[i].tag == "NNP" and text.isalpha() and len(text) >= 3
                                          and text[:1].isupper() and text[1:].islower())):
        return False
    if s.low[i] in lx.NON_PEOPLE or s.low[i] in lx.ROBOT_WORDS or s.index.knows(s.lemma(i)):
        return False
    sentence = s.sentence_of(i)
    first = next(k for k in range(s.n) if s.sentence_of(k) == sentence)
    if s.low[first] not in _PLACING or s.w[first].tag != "VB":
        return False
    return any(s.index.knows(s.lemma(k)) for k in range(i + 2, min(i + 6, s.n)))
