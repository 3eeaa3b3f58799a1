"""A fronted stay said by where it was spent (round 27): "After 40 mins in the waiting hall, a retired
farmer finally goes up to counter 2", "After an hour at the bar, two fans stagger to the exit", "After
twenty minutes of waiting in reception, ...". The length is a stay when a place phrase ("in", "at",
"on", "by" and a word of the world's places) or "of" and a verb's "-ing" form follows it; "After five
minutes, ..." alone is only a time and "After ten minutes the bus comes" keeps no stay.
"""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

_AT = frozenset({"in", "at", "on", "by", "inside", "outside", "near", "beside"})
_DETERMINERS = frozenset({"the", "a", "an", "this", "that", "his", "her", "their", "our", "my"})


def stay_place_after(s: Sentence, k: int) -> bool:
    """Whether the words at k say where a fronted length was spent ("in the waiting hall", "of
    queuing"), up to the clause's comma."""
    if k + 1 >= s.n:
        return False
    if s.low[k] == "of" and s.low[k + 1].endswith("ing"):
        return True
    if s.low[k] not in _AT:
        return False
    j = k + 1
    while j < s.n and s.low[j] in _DETERMINERS:
        j += 1
    end = j
    while end < s.n and not s.is_punct(end):
        end += 1
    return end < s.n and s.low[end] == "," and any(s.index.knows(s.lemma(x)) or s.index.knows(s.low[x])
                                                  for x in range(j, end))
