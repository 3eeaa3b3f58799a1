"""The robot showing people somewhere (round 25): "the robot shows 3 tourists from the ticket office to
platform 2", "shows them the way to the lifts", "shows the new starter to her desk". Showing is one of
the robot's services where it stands ("shows the exhibits"), but with people and a place gone to it is
leading them there: a crossing that takes them along. Showing people round a place ("shows visitors
round the great hall") is the same tour through it."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.sentence import Sentence

_GOING_TO = frozenset("to towards toward into onto".split())
# "shows visitors round the great hall": a tour of a place, taking them along through it (round 26).
_ROUND = frozenset("round around about through".split())
_SHOWING = frozenset({"show"})


def shows_the_way(s: Sentence, verb: int | None, tokens: Sequence[int]) -> bool:
    """Whether the robot's verb at `verb` shows someone to a place: "show", then a destination
    preposition before the clause ends with a verb of its own."""
    if verb is None or s.verb(verb) not in _SHOWING:
        return False
    for k in tokens:
        if k <= verb:
            continue
        if s.low[k] in _GOING_TO and k + 1 < s.n and not s.verb_follows(k + 1):
            return True
        if s.low[k] in _ROUND and k > verb + 1 and k + 1 < s.n and not s.verb_follows(k + 1) and \
                not s.is_punct(k + 1):
            return True  # "shows two new nurses round the ward": leading them through it
        if s.is_verb(k) and k > verb + 1 and s.w[k].tag in ("VBZ", "VBD", "VBP"):
            return False
    return False
