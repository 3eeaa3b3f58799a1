"""A thing of a person named, round 34: "Mr Kowalski shuffles back to his own bed" in a care home whose
room 2 is his ("Mr Kowalski's room") and holds room_2_bed. As for "her room" of a named resident
(language/named_owners.py), the name decides; for a thing, not a room, the one of that kind called
after the name, else the one in the room called after the name."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.places import PlaceEntry, PlaceIndex


def _called(e: PlaceEntry, owner: Sequence[tuple[str, ...]]) -> bool:
    n = len(owner[0])
    return any(phrase[x:x + n] in owner for phrase in e.phrases for x in range(len(phrase) - n + 1))


def things_of_name(index: PlaceIndex, owner: Sequence[tuple[str, ...]], head: str) -> list[PlaceEntry]:
    """The things (not rooms) called `head` that are called after the owner's name, else those in the
    one room called after it."""
    things = [e for e in index.entries if e.kind != "zone" and head in e.tokens]
    named = [e for e in things if _called(e, owner)]
    if named:
        return named
    rooms = {e.name for e in index.entries if e.kind == "zone" and _called(e, owner)}
    return [e for e in things if e.zone in rooms] if len(rooms) == 1 else []
