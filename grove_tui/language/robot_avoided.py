"""A place the robot keeps out of, said before it ("Avoiding the cafeteria, the robot drives to the
pharmacy"; "keeping out of", "without going through" are read as "avoiding" by kept_away.py): the
fronted phrase belongs to the robot's clause, so its place is one the robot does not use."""

from __future__ import annotations

from collections.abc import Collection

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence


def fronted_avoiding(s: Sentence, first: int, taken: Collection[int]) -> int:
    """The first word of an "avoiding ..." phrase that opens the sentence or clause and ends in a comma
    just before the robot's phrase at `first`; else `first`."""
    comma = first - 1
    if comma < 1 or s.low[comma] != ",":
        return first
    a = comma
    while a > 0 and s.w[a - 1].sentence == s.w[comma].sentence and s.low[a - 1] not in (";", ":", ","):
        a -= 1
    if s.low[a] not in lx.NOT_USING_WORDS - {"not", "never"} or a + 1 >= comma:
        return first
    if any(k in taken or s.low[k] in lx.ROBOT_WORDS for k in range(a, comma)):
        return first  # people or the robot in it: not the robot's way alone
    return a
