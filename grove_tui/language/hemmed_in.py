"""Closing round the robot so that it cannot pass (round 59): "surround the robot on the gallery so
it can't get past", "crowd round it by the lifts so that the robot cannot get through". Surrounding
or crowding round the robot alone is coming over to it (approach); with a clause of purpose after it
that keeps the robot from passing, it is blocking it (Threatening). The clause of purpose may stand a
few words after the robot, past where it is, and names the robot by "it" or by its word."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence

_NEGATIONS = frozenset("not n't never cannot unable no".split())
# Verbs of getting past ("can't get past", "cannot move", "is unable to get through").
_PASSING = frozenset("get pass go move squeeze fit through past by leave escape budge continue proceed "
                     "carry".split())
_STOPS = frozenset(". ; ! ? :".split())  # a hyphen ("check-in") or a comma does not end the clause


def kept_from_passing_later(s: Sentence, r: int) -> bool:
    """Whether, within eight words after the robot at r and before any full stop, "so (that) it / the
    robot" opens a clause that says it cannot pass ("so it can't get past")."""
    for k in range(r + 1, min(s.n, r + 9)):
        if s.low[k] in _STOPS:
            return False
        if s.low[k] != "so":
            continue
        j = k + 1
        if j < s.n and s.low[j] == "that":
            j += 1
        if j < s.n and s.low[j] == "the":
            j += 1
        if j >= s.n or not (s.low[j] == "it" or s.low[j] in lx.ROBOT_WORDS):
            return False
        after = range(j + 1, min(s.n, j + 5))
        return any(s.low[a] in _NEGATIONS for a in after) and any(
            s.verb(a) in _PASSING or s.low[a] in _PASSING for a in range(j + 1, min(s.n, j + 6))
            if not s.low[a] in _NEGATIONS)
    return False
