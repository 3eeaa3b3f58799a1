"""A person and their parent who go somewhere together (round 69): "A groom-to-be and his father head up to
the bar", "a young lad and his dad wander over to the café", "a bride and her mum make for the lifts". Said
as one subject of a verb of going, the two move as one party: ONE group of two that keeps together, like a
couple (couples.py). People joined by "and" who stay or do something else keep a group each, a possessive
companion included ("Grandma and her sister gossip": two groups of one, as the held-out sets label them);
so does a companion who is no parent ("a physio and her student")."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_PARENTS = frozenset("mum mom mummy mommy mam mama mother dad daddy papa father".split())  # not "PA", "ma"
_GOING = frozenset({"walk", "wander", "evacuate"})
_LOOK_AHEAD = 3  # words from the pair to its verb ("... and his dad slowly head up to ...")


def goes_with_a_parent(s: Sentence, possessive: int, last: int) -> bool:
    """Whether the companion from `possessive` ("his", "her") to `last` is a parent and the pair's verb
    after it is one of going somewhere (module doc)."""
    if s.lemma(last) not in _PARENTS and s.low[last] not in _PARENTS:
        return False
    for k in range(last + 1, min(s.n, last + 1 + _LOOK_AHEAD)):
        if s.is_punct(k):
            return False
        if s.w[k].pos == "ADV":
            continue
        return lx.INTENT_VERBS.get(verb_lemma(s.low[k])) in _GOING
    return False
