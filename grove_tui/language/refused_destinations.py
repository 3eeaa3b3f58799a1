"""A place refused as one the world lacks is still where people are going (round 56): "four lads
stroll out of the tea room towards the beer tent" is a slow walk somewhere, not a wander about the
room. clauses._main_intent reads a stroll as a walk when the clause has a destination; a refused place
has no match to count, so the words "to"/"towards" before it (kept by place_phrases) count instead,
when they follow the clause's verb with no clause break between.
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.sentence import Sentence

_BREAKS = frozenset("and while but then as whereas when".split())


def refused_destination_after(s: Sentence, candidates: Sequence[tuple[int, str, str]], towards: Sequence[int]) -> bool:
    """Whether "to"/"towards" a refused place (word indexes `towards`) follows a verb of the clause (module doc)."""
    for at in towards:
        for x, _, _ in candidates:
            if x < at and not any(s.is_punct(y) or s.low[y] in _BREAKS for y in range(x + 1, at)):
                return True
    return False
