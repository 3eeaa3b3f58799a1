"""A wait said before a queue: "sit in the waiting room for five minutes before queuing at reception",
"wait by the kiosk for a minute, then join the queue", "join the queue after waiting in the café for
five minutes". The group's intent is the queue; its seconds belong to the wait, which comes first.

"Five people from the café queue at the pharmacy for three minutes" has no verb of waiting beside
the queue's, and "queue at the pharmacy for three minutes, then wait in the café" puts the seconds
after the queue's verb: in both the seconds are the queue's own.
"""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.counts import duration_at
from grove_tui.language.sentence import Sentence
from grove_tui.language.verb_classes import phrasal_intent, verb_intent

# Kinds of staying put whose length can come before a queue.
_STAYS = frozenset({"wait", "converse", "wander"})
# Words that put a later-said verb first: "queue after waiting", "once they have sat".
_EARLIER = frozenset({"after", "once"})


def wait_before_queuing(s: Sentence, span: tuple[int, int], queue_at: int | None) -> tuple[int, int] | None:
    """(the index of the verb of waiting, of its length) when the seconds said in the words of `span`
    are a stay before the queue whose verb is at `queue_at`; else None."""
    if queue_at is None:
        return None
    first, end = span
    said = next((k for k in range(first, end) if duration_at(s, k) is not None), None)
    if said is None:
        return None
    for i in range(first, end):
        if i == queue_at or s.after_determiner(i) or _stay_kind(s, i) not in _STAYS:
            continue
        if i < said < queue_at:
            return i, said  # "sits in the waiting room for five minutes before queuing"
        if queue_at < i < said and any(s.low[k] in _EARLIER for k in range(max(first, i - 3), i)):
            return i, said  # "joins the queue after waiting in the café for five minutes"
    return None


def _stay_kind(s: Sentence, i: int) -> str | None:
    phrasal = phrasal_intent(s, i)  # "hang about", "take a seat"
    if phrasal is not None:
        return phrasal[1]
    if lx.INTENT_VERBS.get(s.verb(i)) == "queue":
        return None
    return verb_intent(s, i)
