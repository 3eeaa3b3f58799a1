"""A place said by what is done there is a room, never a thing in it (round 31): "cross to the place where
they project the stars onto the ceiling" is the dome theatre, not its star projector; "wait in the room
where the vets scrub up" is the prep room, not its sink. When such a phrase ("the place / room / area /
spot where ...") was read as a fixture of the world, the place is the zone that holds it, in the role
its preposition gives (to: destination; from: start; at, in: location). A fixture people go up to and
use (a counter, a desk, a machine) stays: "the place where you get cash out" is the cash machine; and a
"spot where" names a point, often the fixture itself ("the spot where visitors light a candle")."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading
from grove_tui.language.places import PlaceIndex

_WHERE = re.compile(r"\b(to|towards|into|from|out\s+of|at|in|inside|by)\s+(?:the\s+|a\s+|an\s+)?(?:[\w'-]+\s+)?"
                    r"(?:place|room|area|space|part|hall)\s+(?:where|in\s+which)\b", re.I)
# Fixtures people go up to and use: "the place where you get cash out" is the cash machine itself.
_SERVING = frozenset("counter desk till tills kiosk kiosks atm cashpoint bar window point booth hatch gate gates "
                     "counters desks cash ticket tickets vending change photo".split())
_ROLE = {"to": "destination", "towards": "destination", "into": "destination", "from": "start",
         "out of": "start", "at": "location", "in": "location", "inside": "location", "by": "location"}


def _with(g: GroupReading, role: str, place: str) -> GroupReading:
    if role == "destination":
        return replace(g, destination=place)
    if role == "start":
        return replace(g, start=place)
    return replace(g, location=place)


def activity_place_zones(index: PlaceIndex, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """Groups whose place said by an activity was read as a fixture get the fixture's zone instead."""
    out: list[GroupReading] = []
    for g in groups:
        for m in _WHERE.finditer(g.text):
            role = _ROLE[" ".join(m.group(1).lower().split())]
            name = getattr(g, role)
            entry = index.entry(name) if name else None
            used = set(entry.name.split("_")) | {t for said in entry.types for t in said.split()} if entry else set()
            if entry is not None and entry.kind == "entity" and entry.zone and index.entry(entry.zone) is not None \
                    and not used & _SERVING:
                g = _with(g, role, entry.zone)
        out.append(g)
    return tuple(out)
