""""Run" with a thing as its object (issue 29): "actors run lines in the green room", "two volunteers run
a quiz in the lounge", "a nurse runs the tea trolley service on the ward". "Run" there is doing or
managing something, not running anywhere: the verb gives no walk, and a place phrase after it says
where they are. A way, a distance or laps run ("run the stairs", "run laps of the hall", "run the length
of the pier") is still moving, and the place words of the world are never such a thing."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence

# Objects of "run" that are ground covered, not a thing done.
_COVERED = frozenset("lap laps length lengths circuit circuits loop loops errand errands way race gauntlet "
                     "marathon mile miles distance course gamut rest risk fun sprint sprints relay".split())


def runs_a_thing(s: Sentence, i: int) -> bool:
    """Whether the verb at i is "run" with a thing done as its parsed object ("run lines", "run a quiz")."""
    if s.verb(i) != "run" or s.w[i].pos != "VERB":
        return False
    for j in range(i + 1, min(s.n, i + 5)):
        if s.is_punct(j) or s.w[j].pos == "ADP":
            return False
        if s.w[j].dep == "dobj" and s.w[j].head == i and s.w[j].pos == "NOUN":
            noun = s.low[j]
            return not (noun in _COVERED or s.lemma(j) in _COVERED or noun in lx.PASSAGE_WORDS or
                        s.lemma(j) in lx.PASSAGE_WORDS or s.index.knows(noun) or s.index.knows(s.lemma(j)))
    return False
