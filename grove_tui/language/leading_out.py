"""People who take others out with no place said: "staff guide passengers out", "a teacher leads the
children outside", "the stewards usher everyone out". The leaders go (out, in an evacuation); those they
take follow them. And (`goes_out_by`) a verb the lexicon lacks before "out of" a place or "out" a door goes out:
"stumble out of the cafe", "Dad storms out the front door"."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.out_of_building import out_of_building
from grove_tui.language.tokens import verb_lemma

if TYPE_CHECKING:
    from grove_tui.language.clauses import Clause
    from grove_tui.language.sentence import Sentence

_OUT_WORDS = frozenset({"out", "outside", "away", "off"})


def leads_out(s: Sentence, start: int) -> bool:
    """Whether the clause from `start` (the leaders' words) has a verb of leading whose particle says
    out, not followed by a place of its own ("guide passengers out", not "guide them out of the café",
    which names where they start)."""
    k = start
    verb = None
    while k < s.n and not (s.is_punct(k) and k > start) and (k == start or s.low[k] not in lx.CLAUSE_STARTERS):
        if verb is None and s.w[k].pos == "VERB" and verb_lemma(s.low[k]) in lx.LEADING_VERBS:
            verb = k
        elif verb is not None and s.low[k] in _OUT_WORDS and (
                k + 1 >= s.n or s.is_punct(k + 1) or s.low[k + 1] in lx.CLAUSE_STARTERS):
            return True
        elif verb is not None and out_of_building(s, k):
            return True  # "leads them out of the building": out, no place named
        k += 1
    return False


def goes_out_by(c: Clause) -> bool:
    """Whether a clause with a verb of its own that gives no intent goes out of a place or out a door (module
    doc); "mucking out the goat pen" (out a zone, or a door it was matched to but not said) is a chore there."""
    return c.has_action and any(p.prep == "from" and p.out_of or p.prep == "out" and p.match is not None
                                and p.match.kind == "door" and bool(set(p.words) & lx.DOOR_WORDS) for p in c.places)
