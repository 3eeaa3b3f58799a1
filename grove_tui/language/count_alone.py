"""A count with no noun, first said of people at a place (round 20): "all 9 in the lounge head to the
dining room", "the twenty in the lounge and four more go ...", "all 7 at the fountain walk to the
exit". Nothing before names who they are, so the number counts people: a count opening its phrase
("all", "the", "those", "these", or nothing before it but punctuation or "and"), then a place
preposition and a place of the world."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.scene_items import scene_imperative

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

_OPENERS = frozenset({"all", "the", "those", "these"})


def people_by_place(s: Sentence, at: int, after: int) -> bool:
    """Whether the count from `at` to `after` stands alone for people at a place (module doc)."""
    if after + 1 >= s.n or s.low[after] not in lx.PLACE_PREPOSITIONS or s.low[after] in ("of", "to", "from"):
        return False
    if at > 0 and s.low[at - 1] not in _OPENERS and s.low[at - 1] != "and" and not s.is_punct(at - 1) and \
            not scene_imperative(s, at - 1):  # "Put three on the bikes and ...": the scene's first item
        return False  # "at 3 in the afternoon", "ward 3 in the east wing": no count of people
    if at > 1 and s.low[at - 1] in _OPENERS and s.low[at - 2] in lx.PLACE_PREPOSITIONS:
        return False  # "of the two in the east wing": a place's number
    k = s.skip(after + 1, {"the", "this", "that", "its", "their", "our"})
    return k < s.n and any(s.index.knows(s.lemma(j)) or s.index.knows(s.low[j]) for j in range(k, min(k + 3, s.n)))
