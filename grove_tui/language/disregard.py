"""Paying the robot no heed said with a noun of looking or heeding (round 20): "not giving the robot a
second glance", "without so much as a look at it", "pays it no mind", "gives the robot no thought".
A negation and such a noun around the robot's word, in the group's own clause, is no reaction to the
robot at all: not the looking the noun names, and not the refusal to give way the negation and
"give" would otherwise read ("not giving the robot a second glance" is no blocking)."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.sentence import Sentence

# Words that deny the heed ("not", "without", "never", "no", "barely").
_DENYING = frozenset("not n't never without barely hardly scarcely no nor".split())
# Nouns of looking or heeding: what is denied to the robot.
_HEED = frozenset("glance look glimpse notice heed mind attention thought regard".split())
_BEFORE, _AFTER = 8, 5


def disregards(s: Sentence, own: Sequence[int], r: int) -> bool:
    """Whether the clause `own` denies the robot at r any heed: a denying word within a few words
    before it (or "no" just after it: "pays it no mind") and a noun of heed near it."""
    near = [k for k in own if r - _BEFORE <= k <= r + _AFTER and k != r and not s.is_punct(k)]
    denied = any(s.low[k] in _DENYING and not (k + 1 < s.n and s.low[k + 1] in ("one", "body")) for k in near)
    heeded = any(s.lemma(k) in _HEED and s.w[k].pos == "NOUN" for k in near)
    return denied and heeded
