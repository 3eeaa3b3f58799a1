"""The people of a place said back with "its" (round 37): "the toy store catches fire and its 20 shoppers
escape", "with part of the away end's roof torn off, its 1,200 occupants evacuate via gate C". "its"
before people is the place said last before them, so they leave from there: a room by its whole name
(or a thing in it, standing for its room), never the robot."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading
from grove_tui.language.places import PlaceIndex
from grove_tui.language.tokens import phrase_lemmas

_WORD = re.compile(r"[a-z0-9][a-z0-9'’-]*")
_MOVING = frozenset({"walk", "evacuate"})
_ROBOT = frozenset({"robot", "droid", "bot", "robots"})
# Words that end a name before them ("the away end's roof").
_POSSESSIVE = re.compile(r"['’]s?$")


def its_people(prompt: str, index: PlaceIndex, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """Groups said as "its <people>" with no start start in the place said last before them."""
    out: list[GroupReading] = []
    low = prompt.lower()
    for g in groups:
        if g.intent in _MOVING and g.start is None and g.location is None and g.who.lower().startswith("its ") and \
                (at := low.find(g.who.lower())) > 0 and (zone := _said_last(index, low[:at])) is not None and \
                zone != g.destination:
            g = replace(g, start=zone)
        out.append(g)
    return tuple(out)


def _said_last(index: PlaceIndex, text: str) -> str | None:
    """The room of the last whole name of a room or a thing in the last sentence of `text`; None when
    none is said, or when the robot is said in it (its own "its")."""
    words = [_POSSESSIVE.sub("", w) for w in _WORD.findall(re.split(r"[.!?;]\s", text)[-1])]
    if set(words) & _ROBOT:
        return None  # "the robot parks and its passengers get off": the robot's
    for j in range(len(words) - 1, -1, -1):
        for end in range(min(len(words), j + 4), j, -1):
            if not words[j:end] or words[j] in ("the", "a", "an"):
                continue
            match = index.match(tuple(phrase_lemmas(words[j:end])))
            if match is not None and match.exact and match.kind != "door":
                return match.zone
    return None

