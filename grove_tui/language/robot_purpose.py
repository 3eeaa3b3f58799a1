"""Where the robot goes, said first as its purpose (round 25): "To reach the toy store, the robot must
squeeze through ...", "In order to get to gate B1, the robot threads past ...". The fronted purpose
belongs to the robot's clause, so its place is the robot's destination, not a group's."""

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
    to = a + 2 if tuple(s.low[a:a + 3]) == ("in", "order", "to") else a
    if to >= comma or s.low[to] != "to" or not s.verb_follows(to + 1):
        return first
    if any(k in taken or s.low[k] in lx.ROBOT_WORDS or (k > to + 1 and s.is_punct(k)) for k in range(a, comma)):
        return first  # people or another clause in it: not the robot's purpose alone
    return a
