"""A thing said with its state, round 34: "fixes a jammed pinsetter", "repairs the broken lift",
"unblocks a blocked sink", "walks to the locked door". A participle before the thing says what state
it is in, not what kind of thing it is: when the world uses the word nowhere, the place is named by the
words after it (the pinsetters, the lifts, the sink), not refused as a kind of thing the world lacks.
Participles in "-ing" are left alone: they name kinds of room too often ("the booking office", "the
changing room")."""

from __future__ import annotations

from grove_tui.language.own_things import past_own
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma

_NOUNS = frozenset({"NOUN", "PROPN"})


def _state_word(s: Sentence, j: int) -> bool:
    """Whether word j is a past participle of a state ("jammed", "broken") the world never uses."""
    w = s.w[j]
    participle = w.tag == "VBN" or (w.pos in ("ADJ", "VERB") and len(w.lower) > 4 and w.lower.endswith("ed"))
    return participle and w.lower.isalpha() and not s.index.knows(lemma(w.lower)) and not s.index.knows(w.lower)


def past_state(s: Sentence, k: int) -> int:
    """Past the state words at k ("the jammed pinsetter": at "pinsetter") when a noun the world knows
    follows them; k itself otherwise. Past "own" after a possessive too ("his own bed": at "bed")."""
    k = past_own(s, k)
    j = k
    while j < s.n and j < k + 2 and _state_word(s, j):
        j += 1
    if j == k or j >= s.n or s.w[j].pos not in _NOUNS and s.w[j].tag not in ("NN", "NNS"):
        return k
    return j if s.index.knows(lemma(s.low[j])) else k
