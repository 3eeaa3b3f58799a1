"""An errand with a thing carried from one place to another (round 32): "takes the morning float from the
strong room through to the counter", "brings the post up from the sorting office to the tills", "takes
the keys over to the office from reception". The thing carried is no place and no wait: the person
walks from the one place to the other, the places read by their whole names. A way said between the two
with "along", "through", "past", "via" or "across" ("from the kitchen along the corridor to bedroom 3") is the
way they go by, not part of the start's name (round 45)."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading
from grove_tui.language.places import PlaceIndex
from grove_tui.language.purposed_places import place_named

_CARRY = (r"(?:take|takes|taking|took|bring|brings|bringing|brought|carry|carries|carrying|carried|fetch|fetches|"
          r"fetching|fetched|wheel|wheels|wheeling|wheeled|ferry|ferries|ferrying|ferried|lug|lugs|lugging|lugged|"
          r"cart|carts|carting|carted|haul|hauls|hauling|hauled|run|runs|running|ran|pop|pops|popping|popped)")
_ADVERB = r"(?:(?:up|down|over|across|round|around|along|through|back|out|in)\s+)?"
_FROM_TO = re.compile(r"\b" + _CARRY + r"\s+(?:[\w'-]+\s+){1,5}?" + _ADVERB + r"from\s+((?:[\w'-]+\s+){1,5}?)"
                      + _ADVERB + r"(?:to|into|onto)\s+((?:[\w'-]+\s*){1,4})", re.I)
_TO_FROM = re.compile(r"\b" + _CARRY + r"\s+(?:[\w'-]+\s+){1,5}?" + _ADVERB + r"(?:to|into|onto)\s+"
                      r"((?:[\w'-]+\s+){1,5}?)from\s+((?:[\w'-]+\s*){1,4})", re.I)


# Words that start a way taken between a start and a destination ("from X along the corridor to Y").
_WAY_WORDS = frozenset("along through past via across".split())


def _split_way(index: PlaceIndex, words: Sequence[str]) -> tuple[list[str], str | None]:
    """The words of a start and the way said after it: "the kitchen along the corridor" is the kitchen,
    by way of the corridor, when both name places of the world; the words whole otherwise."""
    low = [w.strip(".,;:!?").lower() for w in words]
    for i, w in enumerate(low):
        if i > 0 and w in _WAY_WORDS:
            start, way = place_named(index, words[:i]), place_named(index, words[i + 1:])
            if start is not None and way is not None and start != way:
                return list(words[:i]), way
    return list(words), None


def _ends(index: PlaceIndex, text: str) -> tuple[str, str, str | None] | None:
    way: str | None = None
    m = _FROM_TO.search(text)
    if m is not None:
        said, way = _split_way(index, m.group(1).split())
        start, end = place_named(index, said), place_named(index, m.group(2).split())
    else:
        m = _TO_FROM.search(text)
        if m is None:
            return None
        end, start = place_named(index, m.group(1).split()), place_named(index, m.group(2).split())
    if start is None or end is None or start == end or way == end:
        return None
    return start, end, way


def carried_errands(index: PlaceIndex, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """People read as staying (or with no start) who carry a thing from one place to another walk it there."""
    out: list[GroupReading] = []
    for g in groups:
        ends = _ends(index, g.text) if g.intent in ("wait", "walk") else None
        if ends is not None and (g.intent == "wait" or g.start is None) and g.destination in (None, ends[1]):
            via = g.via if ends[2] is None or ends[2] in g.via else (*g.via, ends[2])
            g = replace(g, intent="walk", start=ends[0], destination=ends[1], location=None, wait_seconds=None, via=via)
        out.append(g)
    return tuple(out)
