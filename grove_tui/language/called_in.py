"""Where a wait ends when someone calls the waiting in (round 28): "a patient perches on the waiting
chairs until the hygienist calls her in", "two clients sit in reception till the manager calls them
through", "a suspect waits at the desk until called in by the custody sergeant". The one who calls
has a room of their own in the world (the hygienist's room, the manager's office): that room is
where the waiting go once called; where they waited is where they start."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma, verb_lemma

_UNTIL = frozenset({"until", "till", "til", "'til", "untill", "when", "once"})
# Verbs of calling or fetching someone in.
_CALLING = frozenset("call summon fetch invite wave beckon usher show collect".split())
# Words after the one called that say in: "calls her in", "calls them through", "shows him back".
_IN = frozenset("in through back inside over up".split())
_STEPS = 8


def _room_of(s: Sentence, k: int) -> str | None:
    """The one zone that belongs to the person word at k ("hygienist": the hygienist's room)."""
    zones = {e.zone for e in s.index.owned_by(s.lemma(k)) if e.kind == "zone"} | \
        {e.zone for e in s.index.owned_by(s.low[k]) if e.kind == "zone"}
    return next(iter(zones)) if len(zones) == 1 else None


def called_in_to(s: Sentence, span: tuple[int, int]) -> str | None:
    """The room of whoever calls the group of `span` in, said in a time clause ending its wait; None."""
    first, end = span
    for u in range(first, min(end, s.n)):
        if s.low[u] not in _UNTIL:
            continue
        words = range(u + 1, min(u + _STEPS, s.n))
        call = next((k for k in words if verb_lemma(s.low[k]) in _CALLING or s.verb(k) in _CALLING), None)
        if call is None or not any(s.low[k] in _IN for k in range(call + 1, min(call + 4, s.n))):
            continue
        # the caller: a person word before the call ("the hygienist calls her in") or after "by"
        before = [k for k in range(u + 1, call) if s.w[k].pos in ("NOUN", "PROPN") and not s.is_punct(k)]
        after_by = [k + 1 for k in range(call + 1, min(call + 5, s.n - 1)) if s.low[k] == "by"]
        after_by = [k + 1 if s.low[k] in ("the", "a", "their", "her", "his") and k + 1 < s.n else k for k in after_by]
        for k in before[-1:] + after_by:
            if s.lemma(k) in lx.ROBOT_WORDS or lemma(s.low[k]) in lx.ROBOT_WORDS:
                continue
            room = _room_of(s, k)
            if room is not None:
                return room
    return None
