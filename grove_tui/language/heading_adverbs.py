"""An adverb of heading after a place ends the place: "carries her from the recital hall back to the
waiting area", "walks from the ward out to the car park", "from the pool area over to the café". The
world may have a name that holds the word ("back row", "out of hours desk"), but said between a place and
a preposition of going the word says which way they go, not which place they left."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma

HEADING_ADVERBS = frozenset("back home away off out over round across along up down on onward onwards".split())
_GOING_ON = frozenset("to into towards toward onto through across past via from".split())


def heading_adverb(s: Sentence, phrase: Sequence[str], j: int) -> bool:
    """Whether the word at j, after the place words `phrase`, heads the movement on ("back to")."""
    if not phrase or s.low[j] not in HEADING_ADVERBS or s.w[j].pos not in ("ADV", "ADP", "PART"):
        return False
    if j + 1 < s.n and s.low[j + 1] not in _GOING_ON and not s.is_punct(j + 1):
        return False
    return (lemma(phrase[-1]), lemma(s.low[j])) not in s.index.name_pairs  # "back row" keeps its "back"
