"""A person's own thing, round 34: "back to his own bed", "to her own room", "at his own desk". "Own"
after a possessive only stresses whose the thing is: the place is the one "his bed" names (the
owner found as for "his bed"), not a kind of bed ("own bed") the world lacks, to refuse."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

_POSSESSIVES = frozenset({"his", "her", "their", "my", "our", "your", "its"})


def past_own(s: Sentence, k: int) -> int:
    """Past "own" at k when a possessive comes right before it ("his own bed": at "bed")."""
    if k < s.n - 1 and k > 0 and s.low[k] == "own" and s.low[k - 1] in _POSSESSIVES:
        return k + 1
    return k
