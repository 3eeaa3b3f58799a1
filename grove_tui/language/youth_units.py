"""A uniformed youth unit named by "pack" ("a Cub pack of about thirty", "the Brownie pack", "a pack of
twelve is waiting"): people, as many as said or as a pack holds, moving together. "Pack" is also a thing
("a pack of crisps") and a verb ("pack up"), so it is a person word only with a capitalised name of the
unit before it or a count of its own after "of" followed by no thing."""

from __future__ import annotations

from grove_tui.language.counts import number_at
from grove_tui.language.sentence import Sentence

_UNITS = frozenset({"pack"})


def youth_unit(s: Sentence, i: int) -> bool:
    """Whether the word at i is a youth unit of people (see the module doc)."""
    if s.lemma(i) not in _UNITS or s.w[i].pos not in ("NOUN", "PROPN"):
        return False
    if i > 1 and s.w[i - 1].text[:1].isupper() and s.w[i - 1].pos in ("NOUN", "PROPN", "ADJ") \
            and s.low[i - 2] in ("a", "an", "the", "our", "their", "his", "her", "my", "local"):
        return True  # "a Cub pack", "the Brownie pack"
    if i + 2 < s.n and s.low[i + 1] == "of":
        k = i + 2 + (1 if s.low[i + 2] in ("about", "around", "roughly", "some", "nearly", "almost") else 0)
        number = number_at(s, k)
        return number is not None and (number[1] >= s.n or s.w[number[1]].pos in ("VERB", "AUX", "ADP", "PUNCT"))
    return False
