"""A room said by its bare number (round 20): "up to 103", "heads back to 104", "across to 212". A
number of three digits or more (not a time: "from 9 to 5") right after a word of going to, which the
world names a place by and which counts no one after it, is that place, not a count. Round 23: said
with a word for number before it ("to number 107", "to no. 109", "to #104"), the number alone."""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence

if TYPE_CHECKING:
    from grove_tui.language.places import PlaceIndex

_TO = frozenset("to towards toward into reach".split())


def bare_room_number(s: Sentence, j: int, is_person_noun: Callable[[int], bool]) -> bool:
    """Whether the number at j is a room's name said alone after "to" (see the module doc)."""
    if not s.low[j].isdigit() or len(s.low[j]) < 3 or j < 1 or s.low[j - 1] not in _TO or not s.index.knows(s.low[j]):
        return False
    after = j + 1
    return after >= s.n or s.is_punct(after) or s.low[after] in lx.CLAUSE_STARTERS or not (
        s.w[after].pos in ("NOUN", "PROPN", "ADJ") or is_person_noun(after))


_NUMBER_WORD = re.compile(r"\b(to|towards|toward|into|reach)\s+(?:number|num\.?|no\.?|nr\.?|#)\s*(\d{3,})\b", re.I)


def without_number_words(text: str, index: PlaceIndex) -> str:
    """The text with the word for number before a room's number after "to" left out, when the world
    names a place by that number: "lets the robot lead her to number 107" is "to 107"."""
    return _NUMBER_WORD.sub(lambda m: f"{m.group(1)} {m.group(2)}" if index.knows(m.group(2)) else m.group(0), text)
