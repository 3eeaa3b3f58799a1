"""Two people under one name (round 33): "Mr and Mrs Obi", "Dr and Mrs Lee", "Mr & Mrs Patel". Two titles
joined by "and" before one surname are a couple, one group of two, wherever it stands: as a subject
("Mr and Mrs Obi walk to ...") or as the people someone escorts ("a salesman escorts Mr and Mrs Obi
from the show floor to the handover bay"), who then go along with the one who escorts them."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence

# Titles that pair in a couple's name ("Mr and Mrs", "Dr and Mrs", "Sir and Lady").
_TITLES = frozenset(lx.TITLES) | frozenset({"lady", "lord", "rev", "reverend"})


def couple_end(s: Sentence, at: int) -> int | None:
    """The last word of a couple's name starting at `at` ("Mr and Mrs Obi": the index of "Obi"), or None."""
    low = s.low
    if at + 3 >= s.n or low[at] not in _TITLES or low[at + 1] not in ("and", "&") or low[at + 2] not in _TITLES:
        return None
    k = at + 3
    while k < s.n and low[k] == ".":
        k += 1  # "Mrs. Obi"
    last = None
    while k < s.n and s.w[k].text[:1].isupper() and s.low[k].replace("-", "").isalpha() and \
            s.low[k] not in lx.ROBOT_WORDS:
        last = k
        k += 1
    return last
