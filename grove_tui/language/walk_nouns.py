"""Verbs of walking in a manner the parser takes for nouns after a noun (round 54): "children from the
village school traipse across to the goats" ("school traipse", a compound), "a gang from the youth club
mooch over to X". With a particle of going after them ("across", "over", "to", "into" ...), they are the
clause's verb, and the noun before them ends the phrase that was taken for a place."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language.manner_walks import MANNER_WALKS
from grove_tui.language.parser import Word
from grove_tui.language.tokens import verb_lemma

_WALKS = frozenset((*MANNER_WALKS.split(), "traipse", "trudge", "mooch", "amble", "saunter", "stroll", "troop",
                    "trek", "wander", "toddle", "waddle", "shuffle", "stride", "march"))
_PARTICLES = frozenset("across over to into in out up down off back along round around through towards toward "
                       "past onto away".split())


def as_walk_verbs(words: list[Word]) -> list[Word]:
    """The parse with a walking verb taken for a noun after a noun, before a particle of going, tagged a verb."""
    out = list(words)
    for k, w in enumerate(words[:-1]):
        if k == 0 or w.pos == "VERB" or words[k - 1].pos not in ("NOUN", "PROPN"):
            continue
        if verb_lemma(w.lower) not in _WALKS or words[k + 1].lower not in _PARTICLES:
            continue
        out[k] = replace(w, pos="VERB", tag="VBD" if w.lower.endswith("ed") else "VBP", dep="ROOT", head=k)
        prev = out[k - 1]
        if prev.dep == "compound" and prev.head == k:
            out[k - 1] = replace(prev, dep=w.dep, head=w.head)  # "the village school": the noun the verb was taken for
    return out
