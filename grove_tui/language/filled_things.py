"""Things people fill, stock or open up (round 33): "a keeper tops up the touch tank", "a porter fills
up the vending machine", "the barman stocks up the bar", "a manager locks up the office". The
particle of such a verb is no way along ("up the corridor"): the thing worked on is where they are,
as with the verbs of cleaning in worked_things.py."""

from __future__ import annotations

# Verbs of filling, stocking, loading, sorting and opening or shutting a thing, with their particles.
FILLING_PARTICLES: dict[str, frozenset[str]] = {
    **{v: frozenset({"up"}) for v in "top fill refill stock restock load reload replenish lock unlock open".split()},
    **{v: frozenset({"up", "out", "away"}) for v in "sort pack unpack".split()},
    **{v: frozenset({"out", "up"}) for v in "check service".split()},
}
