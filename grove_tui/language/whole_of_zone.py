"""A room said for the people in it (round 44): "all of the circle, roughly 300 punters, escapes via the
circle exit", "the whole of the stalls, some 500 fans, leaves by the main doors", "everyone of the
upper tier". The room is where they are: where they start when they go, where they stay when they
stay. The people pass read "all of the circle" as people with no place, and the room only as named
(or, from an earlier scene phrase, as a way through)."""

from __future__ import annotations

import re
from dataclasses import replace

from grove_tui.language.model import GroupReading, PromptReading
from grove_tui.language.places import PlaceIndex
from grove_tui.language.tokens import phrase_lemmas

_WHOLE_OF = re.compile(r"\b(?:all|the\s+whole|the\s+entirety|everyone|everybody)\s+of\s+(?P<the>the\s+)?"
                       r"(?P<words>[a-z][\w-]*(?:\s+[\w-]+){0,2})", re.IGNORECASE)
_STAYING = frozenset({"wait", "queue", "converse", "sit", "stand", "watch"})


def _zone_said(index: PlaceIndex, words: str) -> tuple[str, str] | None:
    """The zone the first one to three words name by a whole name or alias, and the words that name it."""
    said = words.lower().split()
    for n in range(len(said), 0, -1):
        match = index.match(phrase_lemmas(said[:n]))
        if match is not None and match.kind == "zone" and match.exact:
            return match.name, " ".join(said[:n])
    return None


def whole_of_zone(text: str, index: PlaceIndex, reading: PromptReading) -> PromptReading:
    """The reading with the people said as a whole room placed in it (see the module doc)."""
    found = [(z, m) for m in _WHOLE_OF.finditer(text) if (z := _zone_said(index, m.group("words"))) is not None]
    if len(found) != 1:
        return reading
    (zone, said), m = found[0]
    phrase = f"of {m.group('the') or ''}{said}".lower()
    groups: list[GroupReading] = []
    for g in reading.groups:
        own = phrase in g.text.lower() or len(reading.groups) == 1
        if own and g.start is None and g.location is None:
            via = tuple(v for v in g.via if v != zone)
            g = replace(g, location=zone, via=via) if g.intent in _STAYING else replace(g, start=zone, via=via)
        groups.append(g)
    return replace(reading, groups=tuple(groups))
