"""The robot going round said in other words: "goes up and down the west mall", "drives back and
forth along the concourse", "trundles to and fro in the lobby" is a patrol of the place, not a crossing."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.sentence import Sentence

_TO_AND_FRO = (("up", "and", "down"), ("back", "and", "forth"), ("to", "and", "fro"), ("round", "and", "round"),
               ("around", "and", "around"), ("up", "&", "down"))


def to_and_fro(s: Sentence, verb: int | None, tokens: Sequence[int]) -> bool:
    """Whether the robot's verb at `verb` goes there and back again, within three words of it."""
    if verb is None:
        return False
    inside = set(tokens)
    for k in range(verb + 1, min(verb + 4, s.n)):
        if any(tuple(s.low[k:k + 3]) == phrase and k + 2 in inside for phrase in _TO_AND_FRO):
            return True
    return False
