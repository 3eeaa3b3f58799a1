"""A crowd piling out of one place onto another (round 26): "the stag party piles out of the buffet onto
platform one", "the kids pile out of the coach into the car park". Piling out is how a crowd leaves,
an evacuation only when nothing else is said; with a place gone on to ("onto", "into", "to", also joined
by "and": "pile out of the bus and into the hall", "and across to the garage"), and nothing urgent, they walk there."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

_MOVING_ON = frozenset({("pile", "out"), ("bail", "out")})
_ON_TO = frozenset("onto into to towards toward".split())
_CLAUSE_END = frozenset(". ; ! ? , and while as but then".split())
# Ways of going on between "and" and the place ("pile out of the mess and across to the garage").
_ON_WAYS = frozenset("across over down up back out round around along straight right off".split())


def moves_on(s: Sentence, verb: int, pair: tuple[str, str]) -> bool:
    """Whether the crowd piling out at `verb` goes on to a place said after it, in its own clause."""
    if pair not in _MOVING_ON:
        return False
    for k in range(verb + 2, min(verb + 12, s.n - 1)):
        j = k + 1
        while j < s.n and j < k + 3 and s.low[j] in _ON_WAYS:
            j += 1  # "and across to the garage", "and straight over to the vans"
        if s.low[k] == "and" and j < s.n and s.low[j] in _ON_TO:
            continue  # "pile out of the bus and into the hall": the same going on
        if s.low[k] in _CLAUSE_END or (k > verb + 2 and s.is_verb(k) and s.w[k].tag.startswith("VB")):
            return False
        if s.low[k] in _ON_TO and not s.verb_follows(k + 1):
            return True
    return False
