"""A call paid at a place on the way (issue 29): "stops by the toy store to buy a gift", "pops by the
pharmacy", "calls in at the kitchen to make a coffee", "swings by the kiosk", "stopped off at the bakery".
These are visits: the person goes to the place. The parser reads "stops" as a stay and "by" as beside
(a wait with no place), or "pops by X" as leaving X; said as "goes to X" the place is where they go.

"stop by X" alone may be standing beside it ("a porter stops by the lifts"): it is a visit only when a
purpose follows the place ("to <do>", "for <something>"). "drop / pop / swing / call by", "in at",
"off at" and "call at" are visits whatever follows. Only a place of the world is visited ("pops by
to say hello" is not touched), and a passive ("is stopped by security") is no visit."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from grove_tui.language.tokens import lemma

if TYPE_CHECKING:
    from grove_tui.language.places import PlaceIndex

_GOING = {"": "go", "s": "goes", "ed": "went", "ing": "going"}
_VERB = r"(?P<verb>stop|drop|pop|swing|swung|call)(?P<end>s|ped|ed|ping|ing)?"
_PARTICLE = r"(?P<particle>by|in\s+at|in\s+by|off\s+at|off\s+by|round\s+at|over\s+at|at)"
_PLACE = r"(?P<det>the|a|an|our|their|his|her|my)\s+(?P<place>(?:[A-Za-z][\w'-]*\s+){0,2}?[A-Za-z][\w'-]*)"
# With a purpose after the place first ("the toy store to buy": the whole name), then without one.
_WITH_PURPOSE = re.compile(rf"\b{_VERB}\s+{_PARTICLE}\s+{_PLACE}(?P<after>\s+(?:to|for)\s+[A-Za-z])", re.IGNORECASE)
_STOPPING_BY = re.compile(rf"\b{_VERB}\s+{_PARTICLE}\s+{_PLACE}(?P<after>)", re.IGNORECASE)
_NOUN_BEFORE = re.compile(r"\b(?:a|an|the|their|his|her|my|our|its|phone|video|quick|brief|short|long|on)\s+$", re.IGNORECASE)
_PASSIVE = re.compile(r"\b(?:is|are|was|were|be|been|being|get|gets|got|getting)\s+$", re.IGNORECASE)


def _ending(verb: str, end: str) -> str:
    """The going form for a verb's ending: "stops" -> "goes", "popped" -> "went", "swung" -> "went"."""
    if verb == "swung" or end in ("ped", "ed"):
        return _GOING["ed"]
    return _GOING["ing" if end in ("ping", "ing") else end]


def as_stopped_by(text: str, index: PlaceIndex) -> str:
    """The text with a visit said by "stops by / pops by / calls in at <a place>" said as "goes to <it>"."""
    def say(m: re.Match[str]) -> str:
        verb, end = m.group("verb").lower(), (m.group("end") or "").lower()
        particle = " ".join(m.group("particle").lower().split())
        if _PASSIVE.search(text[:m.start()]):
            return m.group(0)  # "is stopped by security": stopped by someone, no visit
        if _NOUN_BEFORE.search(text[:m.start()]):
            return m.group(0)  # "on a call at her desk", "a quick stop by the kiosk": a noun, no visit
        if particle == "at" and verb != "call":
            return m.group(0)  # "stops at the door", "drops at the finish": no visit
        if verb == "stop" and particle == "by" and not m.group("after"):
            return m.group(0)  # "a porter stops by the lifts": standing beside them
        if not any(index.knows(lemma(w.lower())) for w in m.group("place").split()):
            return m.group(0)  # no place of the world
        return f"{_ending(verb, end)} to {m.group('det')} {m.group('place')}{m.group('after') or ''}"
    return _STOPPING_BY.sub(say, _WITH_PURPOSE.sub(say, text))
