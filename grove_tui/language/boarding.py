"""Where a conveyance is boarded (round 18): "run for the train" goes to a platform, "dash for their
flight" to a gate, "hurry to catch the bus" to a bus bay or stand. A purpose that only names a
conveyance names no place by its words; the place is the world's kind of place for boarding it,
the room first, then a thing; among several, the nearest in meaning to boarding it there."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.places import PlaceIndex, PlaceMatch

Decided = tuple[PlaceMatch, float, str, tuple[str, ...]]

# Conveyances and the words of the places they are boarded at.
_BOARDED_AT: dict[str, frozenset[str]] = {
    **{w: frozenset({"platform"}) for w in "train trains tube metro tram underground subway".split()},
    **{w: frozenset({"gate"}) for w in "flight flights plane aeroplane airplane".split()},
    **{w: frozenset({"bay", "stand", "stop"}) for w in "bus buses coach coaches".split()},
    **{w: frozenset({"boarding", "gangway", "pier", "berth", "quay"}) for w in "ferry boat ship crossing".split()},
}
# Words before the conveyance in such a purpose ("for the train", "to catch their flight").
_LEAD = frozenset("for to catch make get the their his her my our a an next last early late connecting".split())


def boarding_place(index: PlaceIndex, words: Sequence[str]) -> Decided | None:
    """The place the conveyance of a purpose (`words`, lower case) is boarded at; None when the
    purpose says more than a conveyance or the world has no such place."""
    said = [w for w in words if w not in _LEAD]
    if len(said) != 1 or said[0] not in _BOARDED_AT:
        return None
    kinds = _BOARDED_AT[said[0]]
    for kind in ("zone", "entity"):
        found = [e for e in index.entries if e.kind == kind and e.tokens & kinds]
        if found:
            break
    else:
        return None
    query = f"where passengers board the {said[0]}"
    ranked = {r.entry.name: r.similarity for r in index.by_description(query)}
    found.sort(key=lambda e: (-ranked.get(e.name, 0.0), e.name))
    best = found[0]
    others = tuple(e.name for e in found[1:3])
    score = 0.8 if not others else 0.55
    return (PlaceMatch(best.name, best.kind, best.zone, 1.0, False), score,
            f"'{' '.join(words)}': boarded at a {'/'.join(sorted(kinds))}, {best.name}", others)
