"""A place said by the things that are there: "to where the washers and dryers are", "wherever the
lockers are". The things are fixtures of the world; the place is the room holding them all (the
laundry, not its machines), so people go to the room and spread in it."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.places import PlaceIndex, PlaceMatch
from grove_tui.language.tokens import phrase_lemmas

Decided = tuple[PlaceMatch, float, str, tuple[str, ...]]

# The verbs that only say the things are there: "where the dryers are", "where the lockers stand".
_BEING = frozenset({"is", "are", "'re", "'s", "were", "was", "be", "sit", "sits", "stand", "stands", "live",
                    "lives", "belong", "belongs"})
_JOINS = frozenset({"and", "or", ",", "&"})
_DETERMINERS = frozenset({"the", "a", "an", "all", "some", "those", "these", "its", "their", "our"})


# Past participles that still only say where the things are ("where the lockers are kept").
_PLACED = frozenset({"located", "situated", "sited", "placed", "housed", "kept", "stored", "stacked", "parked",
                     "lined", "found", "set", "left", "hung", "racked", "moored"})


def _done_to_them(low: Sequence[str], verb: int) -> bool:
    """Whether a passive follows the verb of being, saying what is done to the things there ("where the
    dinghies are launched"): a room where that is done, for where_clause, not the room that holds them."""
    nxt = low[verb + 1] if verb + 1 < len(low) else ""
    return low[verb] in ("is", "are", "were", "was", "be") and nxt.endswith("ed") and nxt not in _PLACED


def _zone_of(index: PlaceIndex, words: Sequence[str]) -> str | None:
    """The zone of the one fixture the words name, None when they name a room or nothing."""
    words = [w for w in words if w not in _DETERMINERS]
    if not words:
        return None
    found = index.match(phrase_lemmas(words))
    if found is None or found.kind == "zone" or not found.exact:
        return None
    return found.zone


def where_things_are(index: PlaceIndex, low: Sequence[str], k: int) -> tuple[Decided, int] | None:
    """At k "where" or "wherever", then things of the world and a verb of being there: the room that
    holds all of them, and the index after the verb; None for any other clause."""
    if k >= len(low) or low[k] not in ("where", "wherever"):
        return None
    verb = next((x for x in range(k + 2, min(len(low), k + 9)) if low[x] in _BEING), None)
    if verb is None or _done_to_them(low, verb):
        return None
    parts: list[list[str]] = [[]]
    for w in low[k + 1:verb]:
        if w in _JOINS:
            parts.append([])
        else:
            parts[-1].append(w)
    zones = {_zone_of(index, part) for part in parts if part}
    if len(zones) != 1 or None in zones or not all(parts):
        return None
    (zone,) = zones
    assert zone is not None
    reason = f"'{' '.join(low[k:verb + 1])}': the room holding them, {zone}"
    return (PlaceMatch(zone, "zone", zone, 1.0, True), 1.0, reason, ()), verb + 1
