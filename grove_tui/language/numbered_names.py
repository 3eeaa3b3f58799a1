"""A place named by a word and its number after "for" (round 46): "leaves the lounge for gate B1",
"quits the ticket hall for platform 2", "sets off for ward 7". With no determiner before it, "for" and a
name were read as a purpose ("for gate B1"), and the place found from that purpose was some other place
(the gate's desk, an office). A word (the tagger may call "gate" an adjective) followed by a number or a letter-and-number ("B1", "2", "12a") that
together name a place of the world is where they go."""

from __future__ import annotations

import re

from grove_tui.language.sentence import Sentence

_NUMBERED = re.compile(r"^(?:[a-z]?\d+[a-z]?)$")


def numbered_name(s: Sentence, k: int) -> bool:
    """Whether the words at k are a noun and its number ("gate b1", "platform 2"), module doc."""
    return k + 1 < s.n and s.low[k].isalpha() and bool(_NUMBERED.match(s.low[k + 1]))
