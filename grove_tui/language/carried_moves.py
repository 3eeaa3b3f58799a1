"""Where a clause's verbs of setting off are, for the room acted on before them (roles.py, `moves_at`).

"Taking" or "bringing" something to a place is setting off with it: "locks her office and takes the
minutes over to the council chamber" starts in her office, as "locks her office and walks to ..." does.
"take" is no verb of walking in the lexicon (one takes a seat, the stairs, a break), so it counts only
with a preposition of going somewhere later in its clause ("to", "over to", "out to", "into")."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Verbs of carrying a thing to a place that are not verbs of walking on their own.
_TAKING = frozenset({"take", "bring", "fetch", "ferry", "deliver"})


def _takes_somewhere(s: Sentence, i: int, end: int) -> bool:
    """Whether word i is "takes"/"brings" with a place it goes to later in its clause."""
    if verb_lemma(s.low[i]) not in _TAKING or s.w[i].pos != "VERB":
        return False
    for j in range(i + 1, end):
        found = s.preposition(j)
        if found is not None and found[0] in lx.DESTINATION_PREPOSITIONS:
            return True
    return False


def moves_at(s: Sentence, span: tuple[int, int]) -> list[int]:
    """The word positions in span of verbs of walking (or of taking something somewhere)."""
    start, end = span
    return [i for i in range(start, end) if not s.after_determiner(i)
            and ((lx.INTENT_VERBS.get(verb_lemma(s.low[i])) in ("walk", "evacuate", "wander")
                  and (s.w[i].pos == "VERB" or not s.index.knows(s.lemma(i))))
                 or _takes_somewhere(s, i, end))]
