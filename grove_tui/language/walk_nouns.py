"""Verbs of walking in a manner the parser takes for nouns after a noun (round 54): "children from the
village school traipse across to the goats" ("school traipse", a compound), "a gang from the youth club
mooch over to X". With a particle of going after them ("across", "over", "to", "into" ...), they are the
clause's verb, and the noun before them ends the phrase that was taken for a place."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.manner_walks import MANNER_WALKS
from grove_tui.language.parser import Word
from grove_tui.language.tokens import lemma

_WALKS = frozenset((*MANNER_WALKS.split(), "traipse", "trudge", "mooch", "amble", "saunter", "stroll", "troop",
                    "trek", "wander", "toddle", "waddle", "shuffle", "stride", "march"))
_PARTICLES = frozenset("across over to into in out up down off back along round around through towards toward "
                       "past onto away".split())


def as_walk_verbs(words: list[Word]) -> list[Word]:
    """The parse with a walking verb taken for a noun after a noun, before a particle of going, tagged a verb: only the base form after a plural subject, where the noun before was taken for its compound
    ("the school traipse"); "-s" forms after a name ("Oliver scurries") are the parser's own business."""
    out = list(words)
    for k, w in enumerate(words[:-1]):
        if k == 0 or w.pos == "VERB" or words[k - 1].pos != "NOUN" or words[k - 1].dep != "compound" or \
                words[k - 1].head != k or lemma(words[k - 1].lower) in lx.PERSON_NOUNS:
            continue  # "40 visitors stroll out": the people, read as the subject by the passes after
        if w.lower not in _WALKS or words[k + 1].lower not in _PARTICLES:
            continue
        out[k] = replace(w, pos="VERB", tag="VBP", dep="ROOT", head=k)
        prev = out[k - 1]
        if prev.dep == "compound" and prev.head == k:
            out[k - 1] = replace(prev, dep=w.dep, head=w.head)  # "the village school": the noun the verb was taken for
    return out
