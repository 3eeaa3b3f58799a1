"""People who join a group said before (round 20): "another 3 join them", "4 more join the queue",
"a few more arrive to queue later". They are more of the earlier group, doing what it does there:
"join" with the group or its queue for object takes the earlier group's intent, and "arrive", "come"
or "turn up" followed by "to" and a verb of intent takes that verb's intent."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import verb_lemma

if TYPE_CHECKING:
    from grove_tui.language.mention import Mention
    from grove_tui.language.sentence import Sentence

_JOINED = frozenset("them us him her the their that this those others rest group queue line".split())
_ARRIVING = frozenset({"arrive", "come", "turn", "show", "roll", "wander", "drift", "trickle"})


def joined_intent(s: Sentence, m: Mention, earlier_intent: str | None) -> str | None:
    """The intent of people counted as more of an earlier group by the verb after them (module doc)."""
    if not (m.relation or "").startswith("more_of:"):
        return None
    k = m.last + 1
    while k < s.n and s.w[k].pos == "ADV":
        k += 1  # "another 3 soon join them"
    if k + 1 >= s.n:
        return None
    verb = verb_lemma(s.low[k])
    if verb == "join" and s.low[k + 1] in _JOINED and not (k + 2 < s.n and s.low[k + 2] in lx.ROBOT_WORDS):
        return earlier_intent
    if verb in _ARRIVING:
        k = s.skip(k + 1, {"up", "in", "along", "over", "later", "soon"})
        if k + 1 < s.n and s.low[k] == "to":
            return lx.INTENT_VERBS.get(verb_lemma(s.low[k + 1]))
    return None
