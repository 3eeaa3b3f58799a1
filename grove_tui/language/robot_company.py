"""People who go with the robot (round 35): "a patient walks with the robot to radiology", "two
visitors stroll alongside it to the café", "the robot is accompanied by a nurse to the pharmacy". They
go where it goes, keeping to it: they follow it, and the robot crosses to where they go
(language/robot_led.py)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import verb_lemma

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

# Words that put someone beside the robot on the way ("walks with", "alongside", "next to" is a place).
_BESIDE_WORDS = frozenset({"with", "alongside", "beside"})
# Passives of keeping someone company: the doers go with the robot ("is accompanied by a nurse").
_COMPANY_PASSIVES = frozenset({"accompany", "join", "escort", "chaperone"})
_GOING_INTENTS = ("walk", "evacuate", "wander")


def goes_with_robot(s: Sentence, own: Sequence[int], r: int) -> str | None:
    """"follow" when the clause's verb of going takes the robot at r along ("walks with the robot",
    "goes along with it", "strolls alongside the robot"), or the robot at r "is accompanied by" the
    clause's people; None otherwise."""
    if r + 3 < s.n and verb_lemma(s.low[r + 1]) in ("be", "get") and verb_lemma(s.low[r + 2]) in _COMPANY_PASSIVES \
            and s.low[r + 3] == "by":
        return "follow"
    k = r - 1
    while k >= 0 and s.low[k] in lx.DETERMINERS:
        k -= 1
    if k >= 0 and k in own and verb_lemma(s.low[k]) == "accompany" and s.is_verb(k):
        return "follow"  # "a nurse accompanies the robot to the pharmacy" (also its passive, said in the active)
    if k < 1 or s.low[k] not in _BESIDE_WORDS:
        return None
    j = k - 1
    if s.low[j] == "along":
        j -= 1
    ownset = set(own)
    if j not in ownset:
        return None
    lemma = verb_lemma(s.low[j])
    if s.is_verb(j) and (lx.INTENT_VERBS.get(lemma) in _GOING_INTENTS or lemma in ("come", "tag", "ride")):
        return "follow"
    return None
