"""A purpose said first, before the people (round 40): "Wanting postcards for their project, a pair of
sixth-formers cross to the museum shop", "Needing a coffee, two nurses walk to the cafeteria", "Seeking
new trainers, three teens wander to the sports shop". Said after the people ("lined up wanting flea
spray") it is read by language/purpose_wanted.py; said first, its phrase opens the sentence and ends at
a comma before the people."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

_WANTING = frozenset("wanting needing seeking".split())
_SENTENCE_ENDS = frozenset({".", "!", "?", ";"})
_REACH = 8  # words from "wanting" to the comma that closes the fronted phrase


def fronted_want(s: Sentence, i: int) -> tuple[int, int] | None:
    """(where the purpose's words start, where its object starts) for "Wanting X, ..." opening a
    sentence at word i, else None."""
    low = s.low
    if low[i] not in _WANTING or not (i == 0 or low[i - 1] in _SENTENCE_ENDS) or i + 1 >= s.n:
        return None
    if s.w[i + 1].pos in ("ADP", "PART", "PRON", "PUNCT", "AUX") or s.preposition(i + 1) is not None:
        return None  # "Wanting to leave, ...", "Needing out, ...": no thing wanted
    if "," not in low[i + 2:i + 2 + _REACH]:
        return None  # no fronted phrase
    return i, i + 1
