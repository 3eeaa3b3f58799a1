"""Crowding round a thing after coming in (round 30): "twenty-odd punters stream in through the doors and
crowd round the hatchback", "a dozen teens rush over and cluster round the fountain", "the kids pour
out of the classroom, then huddle around the climbing frame". After a verb of moving, the thing they
gather round is where they go: their destination, not where they start nor wait.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading
from grove_tui.language.places import PlaceIndex

_GATHER = r"(?:crowd|gather|cluster|huddle|mass|throng|bunch|swarm|congregate)(?:s|es|ed|ing)?"
_AFTER_MOVING = re.compile(r"\b(?:and|then|before)\s+(?:(?:all|quickly|soon|promptly|eagerly|then)\s+)?" + _GATHER +
                           r"\s+(?:a)?round\s+(?:(?:the|a|an|that|this|their|our)\s+)?((?:[\w'-]+\s*){1,4})", re.I)
_MOVING = re.compile(r"\b(?:stream|pour|flood|rush|run|ran|walk|wander|come|came|troop|file|head|hurr|dash|race|stroll|"
                     r"amble|pile|spill|drift|saunter|march|traipse|go|went|arrive|enter|burst|surge|scamper|"
                     r"scurr|trot|jog|tramp|stride|strode|make|made|mak|flock|charg|spill|bound|sprint|nip|pop)\w*\b",
                     re.I)
_STOPS = frozenset("in on at by near to from with for while as and then, . before after".split())
_ROBOT = frozenset("robot it droid bot machine".split())


def _thing(index: PlaceIndex, words: Sequence[str]) -> str | None:
    phrase: list[str] = []
    for w in words:
        w = w.strip(".,;:!?").lower()
        if not w or w in _STOPS:
            break
        phrase.append(w)
    if not phrase or phrase[0] in _ROBOT:
        return None
    for end in range(len(phrase), 0, -1):
        found = index.match(phrase[:end])
        if found is not None and found.exact:
            return found.name
    return None


def crowding_round(index: PlaceIndex, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """Groups that move and then crowd round a place go to it."""
    out: list[GroupReading] = []
    for g in groups:
        m = _AFTER_MOVING.search(g.text)
        place = _thing(index, m.group(1).split()) if m and g.intent in ("walk", "wait", "wander") and g.destination is None \
            else None
        if m is not None and place is not None and _MOVING.search(g.text[:m.start()]):
            g = replace(g, intent="walk", destination=place, start=None if g.start == place else g.start,
                        location=None, wait_seconds=None if g.intent == "wait" else g.wait_seconds)
        out.append(g)
    return tuple(out)
