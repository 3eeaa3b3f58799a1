"""A word for people that is also a vehicle, said as the vehicle (round 27): "until the Glasgow
coach comes", "when the 10.15 coach pulls in", "before the next coach leaves", "they catch the
airport coach". A "coach" that a vehicle's words go with (a place or a time it runs to or at, "the
next", "the last"), that arrives, leaves or pulls in after "until", "when" or "before", or that
people catch, board or miss, is the bus, no person of the scene (a team's coach "waits in the
changing rooms" and "the coach arrives at the pitch" keep their reading)."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

_VEHICLE_NOUNS = frozenset({"coach", "coaches"})
# Verbs a vehicle does in a clause of time.
_VEHICLE_GOES = frozenset("arrive come leave depart pull draw turn roll get go set show appear".split())
# Verbs whose object is the vehicle one rides.
_RIDDEN = frozenset("catch board miss take ride await".split())
_TIME_WORDS = frozenset({"until", "till", "til", "when", "before", "once", "as", "after"})
# Words before "coach" that only a vehicle has.
_VEHICLE_MODIFIERS = frozenset("next last first late early express airport tour holiday night morning evening "
                               "afternoon overnight shuttle replacement return connecting delayed".split())


def coach_as_vehicle(s: Sentence, i: int) -> bool:
    """Whether word i is "coach" said as the vehicle (see the module doc)."""
    if s.low[i] not in _VEHICLE_NOUNS:
        return False
    first = i
    while first > 0 and s.w[first - 1].head == i and s.w[first - 1].dep in ("compound", "amod", "nummod", "nmod"):
        first -= 1
    modifiers = range(first, i)
    vehicle_said = any(s.w[k].tag == "NNP" or s.w[k].pos == "NUM" or s.low[k] in _VEHICLE_MODIFIERS or
                       any(c.isdigit() for c in s.low[k]) for k in modifiers)
    w = s.w[i]
    head = w.head
    if w.dep in ("dobj", "pobj") and head != i:
        verb = head if w.dep == "dobj" else s.w[head].head
        if s.verb(verb) in _RIDDEN or (w.dep == "pobj" and s.low[head] == "for" and s.verb(verb) == "wait"):
            return True  # "catch the coach", "wait for the coach"
    if w.dep != "nsubj" or head == i or s.verb(head) not in _VEHICLE_GOES:
        return False
    before = s.low[first - 1] if first > 0 else ""
    if before in ("the", "a", "an") and first > 1:
        before = s.low[first - 2]
    return vehicle_said or before in _TIME_WORDS
