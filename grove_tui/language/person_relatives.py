"""A place word inside a relative clause about a person (issue 29): "wheels a teenager who slipped on the
wet tiles out of the river", "helps a boy who tripped over a hosepipe to the first aid room". The clause
says what happened to the person before the scene ("who" and a past verb, maybe after "had" or "'d"): the
phrase after its preposition is no place of the scene, so no unknown place is refused over it when the
world lacks it."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_AUX = frozenset("had 'd ’d has have was were".split())
_ADVERBS = frozenset("just earlier already badly nearly".split())


def in_persons_relative(s: Sentence, at: int) -> bool:
    """Whether the preposition at `at` follows "who" and a past verb ("who slipped on", "who'd fallen off")."""
    v = at - 1
    if v < 1 or s.w[v].tag not in ("VBD", "VBN") and verb_lemma(s.low[v]) == s.low[v]:
        return False
    j = v - 1
    while j >= 1 and (s.low[j] in _ADVERBS or s.low[j] in _AUX):
        j -= 1
    return j >= 1 and s.low[j] == "who"
