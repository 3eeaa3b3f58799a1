"""An errand with a thing carried from one place to another (round 32): "takes the morning float from the
strong room through to the counter", "brings the post up from the sorting office to the tills", "takes
the keys over to the office from reception". The thing carried is no place and no wait: the person
walks from the one place to the other, the places read by their whole names."""

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


def _ends(index: PlaceIndex, text: str) -> tuple[str, str] | None:
    m = _FROM_TO.search(text)
    if m is not None:
        start, end = place_named(index, m.group(1).split()), place_named(index, m.group(2).split())
    else:
        m = _TO_FROM.search(text)
        if m is None:
            return None
        end, start = place_named(index, m.group(1).split()), place_named(index, m.group(2).split())
    if start is None or end is None or start == end:
        return None
    return start, end


def carried_errands(index: PlaceIndex, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """People read as staying (or with no start) who carry a thing from one place to another walk it there."""
    out: list[GroupReading] = []
    for g in groups:
        ends = _ends(index, g.text) if g.intent in ("wait", "walk") else None
        if ends is not None and (g.intent == "wait" or g.start is None) and g.destination in (None, ends[1]):
            g = replace(g, intent="walk", start=ends[0], destination=ends[1], location=None, wait_seconds=None)
        out.append(g)
    return tuple(out)
