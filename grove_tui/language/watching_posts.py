"""Watching at a post said by a verb of perceiving with nothing perceived (round 34): "have two
instructors spotting by the cave", "two stewards are spotting at the front", "a guard observing from
the balcony". Someone who perceives what sets the scene off is no group (`perceivers.py`: "a guard
notices smoke in the lab and the students leave"); a verb of perceiving with no object, followed by
a place or nothing, says only where they watch, so they are a group there like any other."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Parts a perceived thing takes in the parse: "spots smoke", "hears that ...", "smells burning".
_OBJECT_DEPS = frozenset({"dobj", "ccomp", "xcomp", "attr", "oprd", "dative"})


def perceives_nothing(s: Sentence, verb: int) -> bool:
    """Whether the perceiving verb at `verb` has no object and a place's preposition, or the clause's end,
    comes right after it ("spotting by the cave", "observing from the balcony", "watching.")."""
    if any(w.head == verb and w.dep in _OBJECT_DEPS and not any(s.is_punct(k) for k in range(verb + 1, w.i))
           for w in s.w):
        return False  # an object after a comma is the next item the parser joined on ("..., a cleaner at")
    nxt = verb + 1
    while nxt < s.n and s.w[nxt].pos == "ADV":
        nxt += 1
    return nxt >= s.n or s.is_punct(nxt) or (s.w[nxt].pos == "ADP" and s.w[nxt].dep in ("prep", "agent"))
