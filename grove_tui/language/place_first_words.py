"""A word alone that begins the names of a room and of fixtures in it names the room: "into departures"
is the departure lounge when the lounge and its departure screens both begin with it, "down to xray" the
radiology department ("xray department") and not its xray machine. A word that only begins another
place's name ("a box" of "box office") names nothing (language/places.py); but when a room and its own
fixtures share that first word, the word says what the room is for, and it is the room people go to.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.places import PlaceEntry


def names_its_zone(entries: Sequence[PlaceEntry], entry: PlaceEntry, head: str) -> bool:
    """Whether `head`, the first word of one of the zone `entry`'s two-word names, also begins a name of a
    fixture inside that zone, so that the word alone names the zone."""
    if entry.kind != "zone" or not any(len(p) > 1 and p[0] == head for p in entry.phrases):
        return False
    return any(e.kind == "entity" and e.zone == entry.name and any(len(p) > 1 and p[0] == head for p in e.phrases)
               for e in entries)
