"""A purpose with its place, said after going off (round 32): "four sneak off for a cuppa in the canteen",
"pop out for a smoke in the yard", "go for lunch in the café", "nip away for a break at the cafe". The
place is where the purpose is had, so it is where they go, not where they start; going off, they walk.
Going out of a place first ("duck out of the lounge for a quick espresso at the café", issue 29), the
place left is where they start and the purpose's place, when none was read, is where they go."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading
from grove_tui.language.places import PlaceIndex
from grove_tui.language.purposed_places import place_named
from grove_tui.language.text import plain

_GOING = (r"(?:off|out|away|over|across|round|around|down|up|along|back|outside|"
          r"go|goes|going|went|gone|head|heads|heading|headed)")
_PURPOSE = re.compile(r"\b" + _GOING + r"(\s+of\s+(?:the\s+|their\s+|his\s+|her\s+|our\s+)?(?:[\w'-]+\s+){0,2}?[\w'-]+)?\s+for\s+(?:a\s+|an\s+|some\s+|their\s+|his\s+|her\s+|a\s+quick\s+|"
                      r"a\s+spot\s+of\s+|a\s+bite\s+of\s+)?(?:[\w'-]+\s+){0,2}?(?:in|at|by|on)\s+(?P<place>(?:[\w'-]+\s*){1,4})",
                      re.I)
_MOVING = frozenset({"walk", "wait", "evacuate", "wander"})


def leisure_places(index: PlaceIndex, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """Groups that go off for a purpose at a place the world has, read as starting there, go there."""
    out: list[GroupReading] = []
    for g in groups:
        m = _PURPOSE.search(g.text) if g.intent in _MOVING else None
        place = place_named(index, [plain(w) for w in m.group("place").split()]) if m is not None else None
        left = place_named(index, [plain(w) for w in m.group(1).split()[1:]]) if m is not None and m.group(1) else None
        read_as_start = g.start == place or (g.location == place and g.destination is None)
        left_first = m is not None and m.group(1) is not None and g.destination is None and g.start != place
        if place is not None and index.entry(place) is not None and (read_as_start or left_first):
            g = replace(g, intent="walk", destination=place, start=(left if left != place else None) if g.start == place else g.start,
                        location=None, wait_seconds=None if g.intent == "wait" else g.wait_seconds)
        out.append(g)
    return tuple(out)
