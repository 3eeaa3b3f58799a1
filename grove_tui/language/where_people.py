"""People who only describe a place: "walks to the room where poorly children wait to be
collected", "to the bar where the regular drinkers sit". A "where" clause after a place tells which
place is meant; the people of its subject are no group of the scene, however many modifiers stand
between "where" and them (a bare "where guests eat" is told apart by the parser's tags already)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.counts import number_at

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

# Words that may stand between "where" and the people it describes ("where poorly children").
_BETWEEN = frozenset({"ADV", "ADJ", "DET", "VERB"})


def describes_a_place(s: Sentence, at: int) -> bool:
    """Whether the phrase at `at` is the subject of a "where" clause after a place noun, with only
    modifiers, no count, between "where" and it."""
    j = at - 1
    while j >= 0 and j >= at - 3 and s.low[j] != "where":
        compound = s.w[j].pos == "NOUN" and s.w[j + 1].pos == "NOUN"  # "where the pottery classes are held"
        if s.w[j].pos not in _BETWEEN and not compound or number_at(s, j) is not None or \
                s.low[j] in lx.CLAUSE_STARTERS:
            return False
        j -= 1
    return (0 < j < at - 1 and s.low[j] == "where" and s.w[j - 1].pos in ("NOUN", "PROPN")
            and s.index.knows(s.lemma(j - 1)) and number_at(s, at) is None)
