"""Things gathered at one place and dropped, handed out or left at another (issue 29): "gathers an armful
of post from the parcel shelves and drops it round the hot desks", "collects the empties from the bar and
takes them back to the kitchen", "grabs the leaflets off the front desk and hands them out in the foyer".
Neither half alone is a route ("from" has no "to" in the same verb's phrase, and "drops it round" is no
going verb), so the person was read as staying at the first place. Gathering from A, then dropping or
taking the things round B, is going from A to B; both places are read by their whole names."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading
from grove_tui.language.places import PlaceIndex
from grove_tui.language.purposed_places import place_named
from grove_tui.language.tokens import lemma

_GATHER = (r"(?:gather|collect|grab|fetch|retriev|scoop|pick|picks|picked|picking|get|gets|got|getting|take|took|"
           r"pull|lift|empt|clear|round)\w*")
_DROP = (r"(?:drop|deliver|leav|left|put|distribut|hand|dish|share|spread|scatter|dump|deposit|plac|post|pass|"
         r"lay|laid|stack|take|took|bring|brought|carr|ferr|wheel|run|ran|pop)\w*")
_PLACE_AT = r"(?:round|around|to|at|on|onto|in|into|among|across|along|by|over|beside|next\s+to)"
_GATHERED_DROPPED = re.compile(
    r"\b" + _GATHER + r"\s+(?:up\s+)?(?:[\w'-]+\s+){1,6}?(?:from|off|out\s+of)\s+((?:[\w'-]+\s+){1,5}?)"
    r"and\s+(?:then\s+)?" + _DROP + r"\s+(?:[\w'-]+\s+){0,3}?(?:(?:off|out|back|down|up|them|it)\s+)?"
    + _PLACE_AT + r"\s+((?:[\w'-]+\s*){1,4})", re.I)


def _named(index: PlaceIndex, said: str) -> str | None:
    """The place the words name whole, as said or by their lemmas ("the hot desks": hot desk)."""
    words = said.split()
    return place_named(index, words) or place_named(index, [lemma(w.strip(".,;:!?").lower()) for w in words])


def _ends(index: PlaceIndex, text: str) -> tuple[str, str] | None:
    m = _GATHERED_DROPPED.search(text)
    if m is None:
        return None
    start, end = _named(index, m.group(1)), _named(index, m.group(2))
    if start is None or end is None or start == end:
        return None
    return start, end


def gathered_and_dropped(index: PlaceIndex, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """People read as staying, or going with no start or no destination, who gather things at one place and drop them at another
    walk from the one to the other."""
    out: list[GroupReading] = []
    for g in groups:
        ends = _ends(index, g.text) if g.intent in ("wait", "walk") else None
        if ends is not None and g.start in (None, ends[0]) and g.destination in (None, ends[1]):
            g = replace(g, intent="walk", start=ends[0], destination=ends[1], location=None, wait_seconds=None)
        out.append(g)
    return tuple(out)
