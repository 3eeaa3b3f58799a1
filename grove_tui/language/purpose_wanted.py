"""A purpose said as what people want (round 26): "lined up at the medicines counter wanting flea spray",
"queue at the pharmacy after painkillers", "waiting at the desk in search of a refund". Read with "in
order to" (language/clauses.py): each gives where the purpose's words start and its verb's place."""

from __future__ import annotations

from grove_tui.language.fronted_wants import fronted_want
from grove_tui.language.paying_purposes import paying_purpose
from grove_tui.language.sentence import Sentence

_WANTING = frozenset("wanting needing seeking hoping".split())


def purpose_said(s: Sentence, i: int) -> tuple[int, int] | None:
    """(where the purpose's words start, where its object starts) for a purpose said at word i, else None."""
    low = s.low
    if low[i] == "in" and i + 2 < s.n and low[i + 1] == "order" and low[i + 2] == "to":
        return i + 2, i + 4  # "in order to catch the bus"
    if low[i] in _WANTING and i > 1 and i + 1 < s.n and s.w[i + 1].pos not in ("ADP", "PART", "PRON", "PUNCT", "AUX") and \
            s.preposition(i + 1) is None and not s.is_punct(i + 1) and s.preposition(i - 1) is None:
        return i, i + 1  # "wanting flea spray": what they want
    if (paying := paying_purpose(s, i)) is not None:
        return paying  # "at the pro's till paying green fees": what they pay for there
    if (fronted := fronted_want(s, i)) is not None:
        return fronted  # "Wanting postcards for their project, a pair of ... cross ..."
    if low[i] == "in" and tuple(low[i + 1:i + 3]) == ("search", "of") and i + 3 < s.n and \
            not s.index.knows(low[i + 3]) and low[i + 3] not in ("the",):
        return i, i + 3  # "in search of a refund"
    return None
