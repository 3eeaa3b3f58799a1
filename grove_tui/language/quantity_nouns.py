"""Nouns of quantity people count with after "a ... of": "a score of pupils" is twenty, "a classful
of children" a school class (25-30, vague). Without this the noun was taken for the person ("score"),
and the people after "of" lost their count."""

from __future__ import annotations

from typing import NamedTuple

from grove_tui.language.sentence import Sentence

# A noun of quantity -> (value, low, high); value > 0 is a number said (a score is twenty), 0 a size
# only implied (a class's 25-30, the school-class size of round 13d).
QUANTITY_NOUNS: dict[str, tuple[int, int, int]] = {
    "score": (20, 20, 20),
    "classful": (0, 25, 30), "classfull": (0, 25, 30), "roomful": (0, 15, 30),
}
# The vague ranges of the sizes only implied, under the kind's word count_of looks up.
VAGUE_QUANTITY_RANGES: dict[str, tuple[int, int]] = {
    noun: (low, high) for noun, (value, low, high) in QUANTITY_NOUNS.items() if value == 0}


class QuantityNoun(NamedTuple):
    value: int  # 0: vague, the word is the kind's key
    word: str
    end: int  # the index after "of"


def quantity_noun_at(s: Sentence, k: int) -> QuantityNoun | None:
    """ "a score of", "a classful of" at word k (the article), with the index after "of"; only with
    "of", so "the score" or "a score" of a match is no count."""
    low = s.low
    if k + 2 >= s.n or low[k] not in ("a", "an", "one") or low[k + 2] != "of":
        return None
    spec = QUANTITY_NOUNS.get(low[k + 1])
    if spec is None:
        return None
    return QuantityNoun(spec[0], low[k + 1], k + 3)
