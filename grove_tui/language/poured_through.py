"""A crowd that pours through a room and then goes on starts in that room (round 53): "fifty tourists
pour through the west lobby and make a beeline for the restrooms", "a school party streams through the
foyer and heads for the cloakroom". A verb of a crowd flowing in, "through" a room (not a door), and
then, joined by "and", going on somewhere: the room is where they come in, their start, not a room
passed on the way. Read after the groups, for a group that goes somewhere and has no start."""

from __future__ import annotations

import re
from dataclasses import replace

from grove_tui.language.model import GroupReading, PromptReading
from grove_tui.language.places import PlaceIndex
from grove_tui.language.tokens import phrase_lemmas

_POURED = re.compile(
    r"\b(?:pour|flood|stream|surge|spill|troop|pile|swarm|flock|file|crowd|teem|cascade)(?:s|es|ed|d|ing|t)?"
    r"\s+(?:in\s+|back\s+)?through\s+(?:the\s+)?(?P<words>[a-z][\w'-]*(?:\s+[\w'-]+){0,2}?)\s*,?\s+(?:and|then)\b",
    re.IGNORECASE)


def _zone_said(index: PlaceIndex, words: str) -> str | None:
    said = words.lower().split()
    for n in range(len(said), 0, -1):
        match = index.match(phrase_lemmas(said[:n]))
        if match is not None and match.kind == "zone" and match.exact:
            return match.name
    return None


def poured_through(text: str, index: PlaceIndex, reading: PromptReading) -> PromptReading:
    """The reading with a crowd poured through a room and going on started in it (module doc)."""
    found = [(z, m) for m in _POURED.finditer(text) if (z := _zone_said(index, m.group("words"))) is not None]
    if len(found) != 1:
        return reading
    zone, m = found[0]
    groups: list[GroupReading] = []
    for g in reading.groups:
        own = m.group("words").lower() in g.text.lower() or len(reading.groups) == 1
        if own and g.intent == "walk" and g.start is None and g.destination not in (None, zone) and zone in g.via:
            g = replace(g, start=zone, via=tuple(v for v in g.via if v != zone))
        groups.append(g)
    return replace(reading, groups=tuple(groups))
