"""A place named by a word and its number after "for" (round 46): "leaves the lounge for gate B1",
"quits the ticket hall for platform 2", "sets off for ward 7". With no determiner before it, "for" and a
name were read as a purpose ("for gate B1"), and the place found from that purpose was some other place
(the gate's desk, an office). A word (the tagger may call "gate" an adjective) followed by a number or a letter-and-number ("B1", "2", "12a") that
together name a place of the world is where they go. A word the world names places by with a number it
lacks ("for ward 7" where the wards are A to D) is a place to refuse, not a purpose (round 48)."""

from __future__ import annotations

import re

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma

_NUMBERED = re.compile(r"^(?:[a-z]?\d+[a-z]?)$")


def numbered_name(s: Sentence, k: int) -> bool:
    """Whether the words at k are a noun and its number ("gate b1", "platform 2"), module doc."""
    return k + 1 < s.n and s.low[k].isalpha() and bool(_NUMBERED.match(s.low[k + 1]))


def numbered_kind(s: Sentence, k: int) -> bool:
    """Whether the words at k are a word the world names places by and a number ("ward 7" where the
    world has wards): a place, refused when the world lacks that number, never a purpose (round 48)."""
    return numbered_name(s, k) and s.index.knows(lemma(s.low[k])) and \
        s.index.match((lemma(s.low[k]), s.low[k + 1])) is None  # nothing of the world near it either
