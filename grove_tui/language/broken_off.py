"""Breaking off from a group to do something at a place (issue 29): "two break off to restock from the
warehouse shelving", "three peel away to fetch trolleys at the car park", "one splits off to grab menus
in the bar". Leaving the others with a purpose whose place comes after it is going to that place, not
waiting where the group is: they walk there, from where they were."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading
from grove_tui.language.places import PlaceIndex
from grove_tui.language.purposed_places import place_named

_LEAVING = (r"(?:break|breaks|breaking|broke|peel|peels|peeling|peeled|split|splits|splitting|splinter|"
            r"splinters|splintered|splintering|branch|branches|branched|branching|drift|drifts|drifted|"
            r"drifting|slip|slips|slipped|slipping)")
_PURPOSE = re.compile(r"\b" + _LEAVING + r"\s+(?:off|away)\s+to\s+[a-z'-]+(?:\s+[\w'-]+){0,3}?\s+"
                      r"(?:from|at|in|on|by|off)\s+((?:[\w'-]+\s*){1,4})", re.I)


def broken_off(index: PlaceIndex, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """Groups that break off to do something at a place the world has, read as waiting, walk there."""
    out: list[GroupReading] = []
    for g in groups:
        m = _PURPOSE.search(g.text) if g.intent == "wait" and g.destination is None else None
        place = place_named(index, m.group(1).split()) if m is not None else None
        if place is not None and index.entry(place) is not None:
            start = g.location if g.location not in (None, place) else g.start
            g = replace(g, intent="walk", destination=place, start=start, location=None, wait_seconds=None)
        out.append(g)
    return tuple(out)
