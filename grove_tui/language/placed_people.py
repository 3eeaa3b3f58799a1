"""A person placed by an imperative, said by a name or a kin word (round 26): "Put Mum on the settee
and leave the robot in the kitchen", "Put Grandad on a bench by the fountain", "Place Tom Hale at the
front desk", "Put a florist by the entrance". The object of the sentence's opening "Put" or "Place"
with a place after it is one person when a capitalised name or a kin word says them, or a noun
whose ending only people's names have ("-ist", "-ian", "-keeper").
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

_PLACING = frozenset({"put", "place", "position", "sit", "seat"})
_WHERE = frozenset("on at in by near beside behind inside outside next".split())


def placed_person(s: Sentence, i: int) -> bool:
    """Whether word i heads the object of an opening placing imperative that names a person."""
    w = s.w[i]
    if w.dep != "dobj" or w.head == i or not s.low[i].isalpha() or len(s.low[i]) < 3:
        return False
    verb = w.head
    if s.low[verb] not in _PLACING or not (verb == 0 or s.is_punct(verb - 1)) or s.w[verb].tag != "VB":
        return False
    if i + 1 >= s.n or s.low[i + 1] not in _WHERE:
        return False
    if not any(s.index.knows(s.lemma(k)) for k in range(i + 2, min(i + 6, s.n))):
        return False  # "Put Starbucks on the map": no place of the world after it
    if s.low[i] in lx.NON_PEOPLE or s.low[i] in lx.ROBOT_WORDS or s.index.knows(s.lemma(i)):
        return False
    first = i
    while first > verb + 1 and s.w[first - 1].head == i and s.w[first - 1].tag == "NNP":
        first -= 1  # "Tom Hale"
    if first == verb + 1 and s.low[i] in lx.KIN_NAMES:
        return True  # "Put Mum on the settee"
    if first == verb + 1 and w.tag == "NNP" and s.w[i].text[:1].isupper() and s.w[i].text[1:].islower():
        return True  # "Put Grandad ...", "Place Tom Hale ..."
    return s.low[first - 1] in ("a", "an", "one") and s.low[i].endswith(lx.STRONG_AGENT_SUFFIXES)
