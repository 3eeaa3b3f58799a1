"""A thing cleared out of a place (round 26): "sweeps spilt popcorn out of screen four", "scoops leaves
from the pond", "pulls weeds out of the rose beds", "mops water out of the foyer". The worker stays in
the place the thing is cleared from: it is where they are, not where they start (a person taken out
of a place is led: language/caused_motion.py)."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma, verb_lemma

_CLEARING = frozenset("sweep mop scrub hose clear wipe brush scoop clean tidy hoover vacuum rake shovel bail pull "
                      "dig weed pick fish gather hoick hook skim dust flush sponge squeegee blow".split())


def cleared_from(s: Sentence, i: int, own: Sequence[int]) -> bool:
    """Whether "from" (or "out of") at i says where a thing is cleared from: a verb of clearing a few
    words before it, a thing (no person) between them."""
    for k in own:
        if not i - 6 <= k < i - 1 or verb_lemma(s.low[k]) not in _CLEARING or \
                k > 0 and s.low[k - 1] in lx.DETERMINERS:
            continue
        between = range(k + 1, i)
        if any(lemma(s.low[x]) in lx.PERSON_NOUNS or s.low[x] in lx.PRONOUN_PEOPLE for x in between):
            return False  # "pulls a drunk out of the bar": a person taken along
        if any(s.low[x] in ("and", ",", "then") for x in between):
            return False
        return any(s.w[x].pos in ("NOUN", "ADJ", "VERB") for x in between)
    return False
