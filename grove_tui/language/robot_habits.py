"""The robot's round said as a habit (round 37): a verb of keeping on, then a verb of going round
("the robot keeps circling the showroom floor", "keeps on looping round the food court", "carries on
touring the galleries", "spends the afternoon circling the lobby", "goes on prowling the concourse"):
the verb of aspect says only that it goes on, the verb it governs says the task, a patrol (or a wait: "keeps waiting by the door")."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence

# Verbs that say another verb goes on ("keeps circling", "carries on looping", "spends an hour touring").
_HABIT_VERBS = frozenset("keep continue carry go spend".split())
# Words between the verb of habit and the verb it governs ("keeps on", "carries on", "spends all day").
_BETWEEN = frozenset("on up just endlessly constantly forever always steadily slowly quietly all the its whole "
                     "entire day morning afternoon evening night shift hour hours time".split())


def habit_task(s: Sentence, verb: int | None) -> str | None:
    """The task a robot's verb of habit governs, a few words on, by its "-ing" verb: going round
    ("keeps circling", "keeps on looping", "spends the day patrolling": patrol) or staying ("keeps
    waiting by the door": wait); None for any other verb."""
    if verb is None or s.verb(verb) not in _HABIT_VERBS:
        return None
    k = verb + 1
    while k < min(s.n, verb + 5) and s.low[k] in _BETWEEN:
        k += 1
    if k >= s.n or not s.low[k].endswith("ing") or (s.verb(verb) == "go" and k == verb + 1):
        return None  # "goes circling": no habit said; "goes on circling" is one
    v = s.verb(k)
    if v in lx.ROBOT_PATROL_VERBS or lx.INTENT_VERBS.get(v) == "wander":
        return "patrol"
    return "wait" if v in lx.ROBOT_WAIT_VERBS and s.verb(verb) != "spend" else None
