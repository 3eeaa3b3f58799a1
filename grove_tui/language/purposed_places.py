"""A purpose that names where people go (round 31): "hurry out of the lounge, late for boarding at B2",
"rush out of the café, off to catch the 9:15 from platform 2", "dash across, in time for their slot in
studio 2", "leave the canteen, due back on the ward". Going with no destination of their own, the place
the purpose is at is where they go: "late for" / "in time for" / "to catch" / "due" and a few words, then
"at"/"in"/"on"/"from" and a place the world has by its whole name (or by a name's number: "B2")."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading
from grove_tui.language.places import PlaceIndex

_LEAD = (r"(?:(?:running|a\s+bit|a\s+little|very|too|already|just)\s+)?late\s+for|(?:just\s+)?in\s+(?:good\s+)?time\s+for|"
         r"early\s+for|on\s+time\s+for|(?:off|hurrying|rushing|dashing|racing|running|trying)\s+to\s+catch|"
         r"to\s+catch|to\s+make|due\s+(?:back\s+)?|expected\s+back|wanted\s+back|needed\s+back")
_PURPOSE = re.compile(r"(?:^|[,;]|\b(?:and|so|as|because|since)\b)\s*(?:[\w'-]+\s+){0,2}?(?:" + _LEAD + r")\s+"
                      r"((?:[\w:'.-]+\s+){0,5}?)(?:at|in|on|from|off|for)\s+((?:[\w'-]+\s*){1,4})", re.I)
_STOPS = frozenset("in on at by near to from with for while as and then but so before after because".split())
_ROBOT = frozenset("robot it droid bot machine".split())
_DETERMINERS = frozenset("the a an their his her its our this that".split())


def place_named(index: PlaceIndex, words: Sequence[str]) -> str | None:
    """The world's place the words (after a preposition) name by a whole name, or by a name's own number
    or code ("B2", "platform 2"); None when they name none."""
    phrase: list[str] = []
    for w in words:
        w = w.strip(".,;:!?").lower()
        if not w or w in _STOPS:
            break
        if not phrase and w in _DETERMINERS:
            continue
        phrase.append(w)
    if not phrase or phrase[0] in _ROBOT:
        return None
    for end in range(len(phrase), 0, -1):
        found = index.match(phrase[:end])
        if found is None:
            continue
        coded = [t for t in phrase[:end] if any(c.isdigit() for c in t)]
        if found.exact or (coded and all(t in found.name.split("_") for t in coded)):
            return found.name
    return None


def purposed_places(index: PlaceIndex, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """Groups that go with no destination, for a purpose at a place the world has, go there."""
    out: list[GroupReading] = []
    for g in groups:
        m = _PURPOSE.search(g.text) if g.intent == "walk" and g.destination is None else None
        place = place_named(index, m.group(2).split()) if m is not None else None
        if place is not None and place != g.start and index.entry(place) is not None:
            g = replace(g, destination=place)
        out.append(g)
    return tuple(out)
