"""Reactions to the robot said by a manner or a situation (round 19). Avoiding it: going past it in a
wary manner ("edges warily past the robot", "creeps nervously by it"), or keeping something between
oneself and it ("keeping the dryers between herself and it"). Blocking it: standing where the robot
wants to go or is going ("deliberately plant themselves where the robot wants to drive", "plants his feet
right where the robot is heading")."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Manners of wariness: going past the robot like this is keeping clear of it.
_WARY = frozenset("warily nervously cautiously gingerly timidly anxiously fearfully apprehensively "
                  "uneasily hesitantly tentatively carefully".split())
_PAST = frozenset("past by around round".split())
_SELVES = frozenset("herself himself themselves itself myself ourselves yourself yourselves her him them us me".split())
# Wanting or trying to go: "where the robot wants to drive", "is trying to pass", "needs to get through".
_WANTING = frozenset("want wants wanted wanting need needs needed needing try tries tried trying mean means "
                     "meant intend intends intended has have had".split())
_GOING = frozenset("go drive pass move get roll travel head cross come through".split())
_UNDER_WAY = frozenset("is are was 's".split())  # "where the robot is heading": its way, going now


def _robot_word(s: Sentence, k: int) -> bool:
    return 0 <= k < s.n and (s.low[k] in lx.ROBOT_WORDS or s.low[k] == "it")


def _wary_past(s: Sentence, ownset: set[int], r: int) -> bool:
    """"(edges) warily past the robot": a manner of wariness, then going past, just before it."""
    k = r - 1 if r > 0 and s.low[r - 1] in lx.DETERMINERS else r
    if k < 1 or s.low[k - 1] not in _PAST:
        return False
    return any(s.low[j] in _WARY for j in range(max(0, k - 5), k - 1) if j in ownset)


def _kept_between(s: Sentence, r: int) -> bool:
    """"keeping the dryers between herself and it": something kept between a person and the robot."""
    k = r - 1 if r > 0 and s.low[r - 1] in lx.DETERMINERS else r
    if k < 3 or s.low[k - 1] != "and" or s.low[k - 2] not in _SELVES or s.low[k - 3] != "between":
        return False
    return any(s.low[j].startswith(("keep", "kept", "put")) for j in range(max(0, k - 9), k - 3))


def _where_it_goes(s: Sentence, ownset: set[int], r: int) -> bool:
    """"(plant themselves) where the robot wants to drive": standing in the way it means to go."""
    k = r - 1 if r > 0 and s.low[r - 1] in lx.DETERMINERS else r
    if k < 1 or s.low[k - 1] != "where":
        return False
    after = [s.low[j] for j in range(r + 1, min(s.n, r + 5))]
    going = [verb_lemma(w) in _GOING for w in after]
    if len(after) >= 2 and after[0] in _UNDER_WAY and after[1].endswith("ing") and going[1]:
        return True  # "where the robot is heading", "where it is going"
    return any(w in _WANTING for w in after[:2]) and any(going[1:])


def manner_reaction(s: Sentence, own: Sequence[int], robot_at: Sequence[int]) -> str | None:
    """"avoid" or "block" said by a manner or a situation (see the module doc); None otherwise."""
    ownset = set(own)
    for r in robot_at:
        if not _robot_word(s, r):
            continue
        if _wary_past(s, ownset, r) or _kept_between(s, r):
            return "avoid"
        if _where_it_goes(s, ownset, r):
            return "block"
    return None
