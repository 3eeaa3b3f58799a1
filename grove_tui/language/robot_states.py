"""The robot staying where it is, said by its state or by whoever puts it there (round 25):

- a word of its state after it, with or without "is" (chat drops it): "bot idle nr pulpit", "the robot
  stationary by gate B1", "robot on standby at the lifts", "the robot is motionless beside the desk";
- a verb of placing it, in the imperative: "park the robot by the back door", "station the robot at the
  information desk", "leave the robot in the lobby", "stick the bot by reception".

Either is a wait at the place its clause names.
"""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_STATES = frozenset("idle idling stationary motionless static parked docked charging asleep dormant immobile "
                    "unmoving inactive".split())
_ON_STATES = frozenset({"standby", "charge"})  # "on standby", "on charge"
_BE = frozenset("is 's was remains stays sits being".split())
_PLACING_VERBS = frozenset("park station position place leave put stick plonk plant dock keep stand".split())


def state_after_robot(s: Sentence, i: int) -> int | None:
    """The index of the word of the robot's state after the robot's word at i ("idle", "on" of "on
    standby"), when what follows it is a place, a new clause or the end; else None."""
    k = i + 1
    if k < s.n and s.low[k] in _BE:
        k += 1
    while k < s.n and s.w[k].pos == "ADV" and s.low[k] not in _STATES:
        k += 1
    if k >= s.n:
        return None
    width = 1 if s.low[k] in _STATES else 2 if s.low[k] == "on" and k + 1 < s.n and s.low[k + 1] in _ON_STATES else 0
    if not width:
        return None
    after = k + width
    if after >= s.n or s.is_punct(after) or s.low[after] in lx.CLAUSE_STARTERS or s.preposition(after) is not None:
        return k
    return None


def placing_robot(s: Sentence, first: int) -> int | None:
    """The index of an imperative verb of placing just before the robot's phrase starting at `first`
    ("park the robot by ...", ", and leave the bot in ..."), at the start of a sentence or clause."""
    v = first - 1
    if v < 0 or verb_lemma(s.low[v]) not in _PLACING_VERBS or s.low[v] != verb_lemma(s.low[v]):
        return None
    if v == 0 or s.is_punct(v - 1) or s.low[v - 1] in lx.CLAUSE_STARTERS | {"please", "just"} \
            or s.w[v - 1].sentence != s.w[v].sentence:
        return v
    return None


def stays_so(s: Sentence, verb: int | None) -> bool:
    """Whether the robot clause's verb at `verb` is a state word or a verb that places it: a wait."""
    if verb is None:
        return False
    if s.low[verb] in _STATES or (s.low[verb] == "on" and verb + 1 < s.n and s.low[verb + 1] in _ON_STATES):
        return True
    return s.low[verb] in _PLACING_VERBS and any(s.low[x] in lx.ROBOT_WORDS for x in range(verb + 1, min(s.n, verb + 4)))
