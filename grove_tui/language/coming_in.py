"""Coming in and then settling somewhere is going there (round 50): "six coders let themselves in by the
rear exit and settle at their desks", "two nurses come in through the side door and sit down at the
station". "let themselves in" is coming in, though "let" is no verb of going; and a verb of sitting down
said after a verb of coming in does not make the clause a wait at the door they came by: they walk in,
and where they sit is where they go.

Round 72: a card or pass swiped at a door or gate ("swipe through the main gate and drift over to ...",
"badge through the turnstiles"): coming in there, so the door is where they start, as "come in through" is."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.sentence import Sentence

_SELVES = frozenset("themselves himself herself ourselves yourselves yourself myself oneself".split())
_IN = frozenset({"in", "into", "inside"})
# Verbs of sitting down somewhere to stay: after coming in, where they end up.
_SETTLING = frozenset({"sit", "settle", "perch"})
_ENTERING = frozenset({"enter", "arrive"})
# Verbs of passing a door by a card or pass: "swipe through the gate" is coming in by it.
SWIPING_VERBS = frozenset("swipe badge tap scan clock buzz".split())


def lets_self_in(s: Sentence, i: int) -> bool:
    """Whether the verb at i is "let" + a reflexive + "in" ("let themselves in"): coming in."""
    return s.verb(i) == "let" and i + 2 < s.n and s.low[i + 1] in _SELVES and s.low[i + 2] in _IN


def _comes_in(s: Sentence, i: int, verb: str) -> bool:
    return verb in _ENTERING or any(s.low[x] in _IN for x in range(i + 1, min(s.n, i + 4)))


def settled_after_coming(s: Sentence, candidates: Sequence[tuple[int, str, str]]) -> tuple[int, str, str] | None:
    """The verb of coming in said before a verb of sitting down ("come in ... and sit down at the desks"):
    the clause is walking there (module doc). None otherwise."""
    sat = next((c for c in candidates if c[1] == "wait" and c[2] in _SETTLING), None)
    if sat is None or any(c[1] not in ("walk", "wait") for c in candidates):
        return None
    return next((c for c in candidates if c[1] == "walk" and c[0] < sat[0] and _comes_in(s, c[0], c[2])), None)
