"""Words that name a couple said bare, with no determiner: "Newlyweds furnishing their first flat go ...",
"Honeymooners stroll to the pier" are one couple, two people together, as "the newlyweds" already were
(lexicon COUPLE_PLURALS); a bare plural was read as a vague crowd of three to six."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence


def bare_couple(s: Sentence, at: int, noun: str) -> bool:
    """Whether the phrase at word `at`, with no determiner, is a plural that names one couple."""
    if noun not in lx.COUPLE_PLURALS:
        return False
    return s.low[at] not in lx.DETERMINERS and (at == 0 or s.low[at - 1] not in ("of", "other", "some", "more"))
