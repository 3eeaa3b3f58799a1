"""A robot that keeps someone company to a place is taking them there (round 61): "the robot accompanies
her back to the waiting lounge", "it accompanies two pensioners to the lifts". A verb of keeping
company ("accompany", "chaperone", or "see" someone to a place) alone reads as the robot following ("the robot accompanies the nurse
on her rounds"), but with an object and then where it goes ("to", "back to", "into", "over to") the
robot leads: it crosses there and the person follows it, as with "guides her back to ..."."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import verb_lemma

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

# Verbs of keeping company that take the person along when a place to go is said after them.
_COMPANY_VERBS = frozenset({"accompany", "chaperone", "see"})  # "sees her back to her seat"
# Words between the person and the place the robot takes them ("back to", "over to", "down into").
_BETWEEN = frozenset({"back", "over", "across", "down", "up", "out", "along", "safely", "all", "the", "way", "home"})
_TO_WORDS = frozenset({"to", "into", "towards", "toward", "onto"})
_OBJECT_PRONOUNS = frozenset({"him", "her", "them", "us", "me"})


def escorts_to_a_place(s: Sentence, verb: int | None) -> bool:
    """Whether the robot's verb at verb keeps someone company to a place said after them (module doc)."""
    if verb is None or verb_lemma(s.low[verb]) not in _COMPANY_VERBS:
        return False
    k = verb + 1
    if k < s.n and s.low[k] in _OBJECT_PRONOUNS:
        k += 1
    else:  # "a bewildered tourist", "two pensioners", "Mr Ali"
        while k < s.n and not s.is_punct(k) and s.low[k] not in _TO_WORDS and \
                s.low[k] not in lx.CLAUSE_STARTERS and s.w[k].pos in ("DET", "NUM", "ADJ", "NOUN", "PROPN", "PRON"):
            k += 1
        if k == verb + 1:
            return False
    while k < s.n and s.low[k] in _BETWEEN:
        k += 1
    return k < s.n and s.low[k] in _TO_WORDS
