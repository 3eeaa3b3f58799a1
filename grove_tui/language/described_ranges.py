"""A range of two small counts said with "or" before a describing word ("nine or ten weekend
decorators", "two or three nervous children", "four or five tired shoppers") is the speaker's estimate:
an approximate count with the two numbers as its range. Before the person noun itself ("two or three
people") the range stays a vague count, as the reader has always read it."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Parts of speech a word describing the person noun after it takes: an adjective ("nervous"), a
# participle ("tired"), or a noun used as a modifier ("weekend decorators").
_DESCRIBING = frozenset({"ADJ", "VERB"})
_NOUNS = frozenset({"NOUN", "PROPN"})


def is_described_estimate(s: Sentence, end: int) -> bool:
    """Whether the range ending before word `end` was said with "or" ("nine or ten") and a describing
    word follows it before the person noun."""
    if end < 2 or end + 1 >= s.n or s.low[end - 2] != "or":
        return False
    if end + 2 < s.n and s.low[end + 1] == "-" and s.hyphen_inside(end + 1):
        return True  # "five or six off-duty porters"
    word, nxt = s.w[end], s.w[end + 1]
    if s.is_punct(end) or s.low[end] in ("of", "and", "or", "to"):
        return False
    if word.pos in _DESCRIBING:
        return nxt.pos in _NOUNS or nxt.pos in _DESCRIBING or s.low[end + 1] == "-"
    if word.pos in _NOUNS:
        return nxt.pos in _NOUNS and nxt.tag in ("NNS", "NNPS")
    return False


_SMALL = {"three": 3, "four": 4, "five": 5, "3": 3, "4": 4, "5": 5}


def couple_or_more(s: Sentence, k: int) -> tuple[int, int] | None:
    """(top, index after) of "a couple or three", "a couple or 4": about two to that many."""
    if tuple(s.low[k:k + 3]) in (("a", "couple", "or"), ("a", "couple", "-")) and k + 3 < s.n:
        top = _SMALL.get(s.low[k + 3])
        if top is not None:
            return top, k + 4
    return None
