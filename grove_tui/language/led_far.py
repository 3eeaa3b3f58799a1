"""What a person is pushed in when a longer description of them stands between the verb and it: "pushes
a girl with a twisted ankle in a wheelchair", "wheels an old lady with a stick in a wheelchair". The
verb of taking someone along is further back than language/movers.py looks (six words), but in the same
clause, and a person is its object: the wheelchair is what carries them, no place (and none to refuse)."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# How far back, in one clause, the verb of taking someone along may be.
_REACH = 12


def led_far_before(s: Sentence, at: int) -> bool:
    """Whether a verb of taking someone along, with a person right after it, stands before word `at` in
    its clause (no punctuation or "and" between), up to twelve words back."""
    from grove_tui.language.movers import moved_person_at

    for x in range(at - 1, max(-1, at - _REACH - 1), -1):
        if s.is_punct(x) or s.low[x] in ("and", "while", "as", "then"):
            return False
        if verb_lemma(s.low[x]) in lx.LEADING_VERBS and moved_person_at(s, x + 1) is not None:
            return True
    return False
