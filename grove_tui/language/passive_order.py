"""Groups of a passive in the order the sentence says them (round 18): "a patient is wheeled to
radiology by a porter" is read in the active ("a porter wheels a patient ..."), which puts the
taker first; the set's convention is the order of first mention, so the taken come first again.
Relations between groups ("subset_of:0") are renumbered with the order.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading


def _said_at(text: str, who: str) -> int:
    """Where the words naming a group first stand in the typed text; -1 when they are not there."""
    found = re.search(r"\b" + re.escape(who.lower()) + r"\b", text.lower()) if who else None
    return found.start() if found else -1


def in_said_order(read: Sequence[GroupReading], typed: str) -> tuple[GroupReading, ...]:
    """The groups with each taken group put back before its taker when the typed text names it
    first (the taker being the group it follows); other groups keep their place."""
    order = list(range(len(read)))
    for k, g in enumerate(read):
        if g.intent != "follow" or g.follows is None:
            continue
        taker = next((j for j in order if read[j].who == g.follows and j != k), None)
        if taker is None or order.index(taker) > order.index(k):
            continue
        at, taker_at = _said_at(typed, g.who), _said_at(typed, read[taker].who)
        if 0 <= at < taker_at:
            order.remove(k)
            order.insert(order.index(taker), k)
    if order == list(range(len(read))):
        return tuple(read)
    new_index = {old: new for new, old in enumerate(order)}
    out: list[GroupReading] = []
    for old in order:
        g = read[old]
        kind, _, parent = (g.relation or "").partition(":")
        if parent.isdigit() and int(parent) in new_index:
            g = replace(g, relation=f"{kind}:{new_index[int(parent)]}")
        out.append(g)
    return tuple(out)
