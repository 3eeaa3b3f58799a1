"""People said in general inside a clause that says which place someone goes to (round 44): "runs to
where staff look after children who got separated from their parents", "walks to where volunteers look
after witnesses". The clause names the place by what is done there; its bare plurals ("children",
"witnesses") are the kind of people it is done for, nobody present, so they are no group. People said
with a determiner, a number or a possessive ("to where her kids are playing") are there, and stay."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.mention import Mention
from grove_tui.language.sentence import Sentence

# Prepositions of going before "where" ("to where", "back towards where").
_GOING_TO = frozenset({"to", "towards", "toward", "into"})


def _clause_of(s: Sentence, i: int) -> bool:
    """Whether word i is inside a "to where ..." clause (up to punctuation or a new clause's "and")."""
    for x in range(i - 1, -1, -1):
        if s.is_punct(x) or s.low[x] in ("and", "but", "while", "as"):
            return False
        if s.low[x] in ("where", "wherever") and x > 0 and s.low[x - 1] in _GOING_TO:
            return True
    return False


def _generic(s: Sentence, m: Mention) -> bool:
    if m.relation is not None or s.w[m.last].tag != "NNS" or \
            any(s.w[x].pos not in ("ADJ", "NOUN") for x in range(m.first, m.last)):
        return False  # "children", "poorly children"; not "the toddlers", "two kids"
    before = s.low[m.first - 1] if m.first > 0 else ""
    return before not in lx.DETERMINERS and not before.isdigit() and before not in lx.UNITS and \
        before not in ("her", "his", "their", "my", "our", "your", "its") and _clause_of(s, m.first)


def without_generic_where_people(s: Sentence, mentions: Sequence[Mention]) -> list[Mention]:
    """The mentions but people said in general in a "to where ..." clause, when someone else is named."""
    kept = [m for m in mentions if not _generic(s, m)]
    return kept if kept else list(mentions)
