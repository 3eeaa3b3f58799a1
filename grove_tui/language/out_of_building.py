"""Taking people out of the whole building (round 35): "the robot leads them out of the building",
"guides the visitors out of the museum", "escorts everyone out of the premises". The phrase names no
place of the world, only the building itself: it says out, as a bare "out" does (language/leading_out.py),
to the building's exit."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

# Words between "of the" and the building word ("out of the main building", "out of the old station").
_BUILDING_MODIFIERS = frozenset("main whole entire old new big same".split())
# Building words that name a part of it, or no thing one is taken out of.
_NOT_WHOLE = frozenset({"floor", "area", "inside", "outside", "interior", "indoors", "outdoors"})


def out_of_building(s: Sentence, k: int) -> bool:
    """Whether "out" at k says "out of the building" (or the premises, or the world's own kind: "out
    of the museum" in the museum), ending its clause: out to an exit, no place of the world named."""
    if k + 2 >= s.n or s.low[k] != "out" or s.low[k + 1] != "of":
        return False
    j = s.skip(k + 2, lx.DETERMINERS | _BUILDING_MODIFIERS)
    if j >= s.n:
        return False
    whole = bool({s.lemma(j), s.low[j]} & (lx.BUILDING_WORDS - _NOT_WHOLE)) or \
        s.low[j] == s.index.world.name.lower()
    end = j + 1
    return whole and (end >= s.n or s.is_punct(end) or s.low[end] in lx.CLAUSE_STARTERS)
