"""Getting away from a person is no evacuation: "A toddler escapes from his mum and runs off into the great
hall", "the dog's owner flees from the angry keeper". "escape" and "flee" say an evacuation when what is
left is a place or a danger ("escape the fire", "flee the building"); from someone they are going off."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma, verb_lemma

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

_GETTING_AWAY = frozenset({"escape", "flee"})
_BEFORE_PERSON = frozenset("the a an his her their my our its your angry cross furious".split())


def escapes_a_person(s: Sentence, i: int) -> bool:
    """Whether word i is "escape" or "flee" with a person after "from" (or as its object): "escapes from his
    mum", "flees her big sister", "escapes away from the nanny"."""
    if verb_lemma(s.low[i]) not in _GETTING_AWAY:
        return False
    k = i + 1
    while k < s.n and s.low[k] in ("away", "from"):
        k += 1
    while k < s.n and (s.low[k] in _BEFORE_PERSON or s.w[k].pos == "ADJ"):
        k += 1
    return k < s.n and k > i + 1 and (lemma(s.low[k]) in lx.PERSON_NOUNS or s.low[k] in lx.PERSON_NOUNS)
