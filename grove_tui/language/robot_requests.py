"""People who let or have the robot take them somewhere: "a guest lets the robot lead her to room 107",
"has the robot show him to the cloakroom", "asks the robot to take her to gate B1", "gets it to walk
them to the exit". The person follows the robot (Curious); the robot crosses where they go
(robot_led.py), and the clause's places stay the person's."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

# Whom the robot is asked to take: the asker, said again by a pronoun ("lets the robot lead her").
_TAKEN = frozenset("him her them me us everyone everybody".split())


def asks_to_be_led(s: Sentence, own: Sequence[int], robot_at: Sequence[int]) -> bool:
    """Whether the clause has the robot at one of `robot_at` told (let, have, ask, get) to lead,
    guide, show or take whom the clause is about."""
    ownset = set(own)
    for r in robot_at:
        k = r - 1
        while k >= 0 and s.low[k] in lx.DETERMINERS:
            k -= 1
        if k < 0 or k not in ownset or s.verb(k) not in lx.ROBOT_COMMAND_VERBS:
            continue
        v = r + 1
        if v < s.n and s.low[v] == "to":
            v += 1
        if v + 1 < s.n and s.verb(v) in lx.LEADING_VERBS and s.low[v + 1] in _TAKEN:
            return True
    return False
