"""A fronted stay said by what was done and where (issue 29): "After forty minutes of silent study in the
quiet room, ...", "After an hour of paperwork at the desk, ...", "After twenty minutes of small talk by
the bar, ...". "of" and a noun of doing (not only a verb's "-ing" form, stay_places.py) with a place
phrase behind it up to the clause's comma is a stay spent at that place: where they start."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence
from grove_tui.language.stay_places import stay_place_after

_DOING_POS = frozenset({"NOUN", "ADJ", "ADV", "VERB", "PROPN"})


def activity_stay_place(s: Sentence, k: int) -> int | None:
    """The index of the preposition of the place after "of <doing>" at k ("of silent study in the quiet
    room": "in"); None when "of" does not open one, or another word comes between."""
    if k >= s.n or s.low[k] != "of":
        return None
    for j in range(k + 1, min(s.n, k + 5)):
        if s.is_punct(j) or s.w[j].pos not in _DOING_POS and s.w[j].pos != "ADP":
            return None
        if j > k + 1 and s.w[j].pos == "ADP":
            return j if stay_place_after(s, j) else None
    return None
