"""People who only describe a place: "walks to the room where poorly children wait to be
collected", "to the bar where the regular drinkers sit", "runs to where staff look after lost children". A "where" clause after a place tells which
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


# Prepositions before "where" that make its clause a place said by what happens there ("runs to where
# staff look after lost children", "heads back to where the coaches park").
_TO_WHERE = frozenset("to towards toward into from back over round around near by past".split())


def _in_a_place_said_by_a_clause(s: Sentence, at: int) -> bool:
    """Whether the phrase at `at` is inside a "where" clause that names a place after a preposition, with
    no clause break between "where" and it: its people, subject or object, only say which place."""
    j = at - 1
    while j >= 0 and s.w[j].sentence == s.w[at].sentence and not s.is_punct(j) and s.low[j] not in ("where", "wherever") and \
            s.low[j] not in lx.CLAUSE_STARTERS - {"with", "after", "before", "as"}:
        j -= 1
    if not (j > 0 and s.low[j] in ("where", "wherever") and s.low[j - 1] in _TO_WHERE):
        return False
    return not _present_now(s, j)


def _present_now(s: Sentence, where: int) -> bool:
    """Whether the "where" clause names people of the scene, there now: someone's own or counted people
    ("to where her two kids are queuing") or people doing it at this moment ("where the guards are
    waiting"), not people said for what usually happens there ("where staff look after lost children")."""
    end = where + 1
    while end < s.n and s.w[end].sentence == s.w[where].sentence and not s.is_punct(end):
        end += 1
    clause = range(where + 1, end)
    if any(s.low[k] in ("her", "his", "their", "our", "my", "your") or s.w[k].pos == "NUM" for k in clause
           if k < where + 4):
        return True
    return any(s.low[k] in ("is", "are") and k + 1 < s.n and s.w[k + 1].tag == "VBG" for k in clause)


def describes_a_place(s: Sentence, at: int) -> bool:
    """Whether the phrase at `at` is the subject of a "where" clause after a place noun, with only
    modifiers, no count, between "where" and it, or anyone in a "where" clause said after a preposition
    (round 44: "runs to where staff look after children who got separated from their parents")."""
    if _in_a_place_said_by_a_clause(s, at):
        return True
    j = at - 1
    while j >= 0 and j >= at - 3 and s.low[j] != "where":
        compound = s.w[j].pos == "NOUN" and s.w[j + 1].pos == "NOUN"  # "where the pottery classes are held"
        if s.w[j].pos not in _BETWEEN and not compound or number_at(s, j) is not None or \
                s.low[j] in lx.CLAUSE_STARTERS:
            return False
        j -= 1
    return (0 < j < at - 1 and s.low[j] == "where" and s.w[j - 1].pos in ("NOUN", "PROPN")
            and s.index.knows(s.lemma(j - 1)) and number_at(s, at) is None)
