"""Where the robot goes, said first as its purpose or its way (round 25): "To reach the toy store, the
robot must squeeze through ...", "In order to get to gate B1, the robot threads past ...", "On its way
to the pharmacy, the robot passes ...", "Heading for gate B1, the robot weaves past ...", "Bound for the
cafe, the robot ...". The fronted phrase belongs to the robot's clause, so its place is the robot's
destination, not a group's."""

from __future__ import annotations

from collections.abc import Collection

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence


def fronted_purpose(s: Sentence, first: int, taken: Collection[int]) -> int:
    """The first word of a purpose ("to" and a verb) that opens the sentence or clause and ends in a
    comma just before the robot's phrase at `first`; else `first`."""
    comma = first - 1
    if comma < 1 or s.low[comma] != ",":
        return first
    a = comma
    while a > 0 and s.w[a - 1].sentence == s.w[comma].sentence and s.low[a - 1] not in (";", ":"):
        a -= 1
    if not _opens_a_way(s, a, comma):
        return first
    if any(k in taken or s.low[k] in lx.ROBOT_WORDS or s.is_punct(k) for k in range(a, comma)):
        return first  # people or another clause in it: not the robot's purpose alone
    return a


_WAY_OPENERS = (("on", "its", "way"), ("on", "the", "way"), ("en", "route"), ("bound", "for"), ("headed", "for"),
                ("headed", "to"), ("heading", "for"), ("heading", "to"), ("heading", "towards"), ("making", "for"),
                ("making", "its", "way"), ("on", "route"))


def _opens_a_way(s: Sentence, a: int, comma: int) -> bool:
    """Whether the words from a to the comma say a purpose ("to reach ...") or a way ("on its way to ...")."""
    to = a + 2 if tuple(s.low[a:a + 3]) == ("in", "order", "to") else a
    if to < comma and s.low[to] == "to" and s.verb_follows(to + 1):
        return True
    return any(tuple(s.low[a:a + len(p)]) == p and a + len(p) < comma for p in _WAY_OPENERS)
