"""Standing before the robot (round 38): "plant themselves before the robot", "stands squarely
before it", "park themselves right before the robot and refuse to move" put the people in front of it,
in its way: block. "Before" is the place in front here, not a time: a time has a verb after the robot
("before the robot arrives", "before it gets to the lifts"), and a clause that says only where people
are in front of it without a verb of standing or a reflexive ("queue before the robot does") is left
alone."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.sentence import Sentence

# Verbs of taking or keeping a stand ("plant themselves", "stands", "stations himself", "squares up").
_STANDING = frozenset("plant stand station park position place put set post stop halt loom hover "
                      "sit squat kneel crouch linger loiter remain stay wait gather cluster huddle line "
                      "form bunch pose".split())
_REFLEXIVES = frozenset("themselves himself herself myself ourselves yourself yourselves".split())
_ADVERBS = frozenset("squarely right directly just firmly defiantly stubbornly deliberately "
                     "menacingly solidly".split())
_DETERMINERS = frozenset("the our this that their a".split())
# What may follow the robot with "before" still the place: a stop, "and", "so", or a participle
# ("barring it").
_TIME_FOLLOWERS = frozenset("can could will would does did is was has had gets comes arrives reaches "
                            "passes leaves goes starts moves rolls".split())


def placed_before(s: Sentence, own: Sequence[int], r: int) -> str | None:
    """"block" when the robot at r comes after "before" that follows a verb of standing, a reflexive
    or an adverb of placing in the same clause ("plant themselves squarely before the robot"), and the
    robot has no verb of its own after it (not "sit down before the robot arrives")."""
    ownset = set(own)
    b = r - 1
    if s.low[r] in ("it",):
        b = r - 1
    elif b >= 0 and s.low[b] in _DETERMINERS:
        b -= 1
    if b < 1 or s.low[b] != "before" or b not in ownset:
        return None
    nxt = r + 1
    if nxt < s.n and not s.is_punct(nxt) and (s.low[nxt] in _TIME_FOLLOWERS or s.w[nxt].pos in ("VERB", "AUX")):
        return None  # "before the robot arrives": a time
    k = b - 1
    while k >= 0 and s.low[k] in _ADVERBS:
        k -= 1
    if k < 0 or k not in ownset:
        return None
    if s.low[k] in _REFLEXIVES or s.verb(k) in _STANDING:
        return "block"
    return None
