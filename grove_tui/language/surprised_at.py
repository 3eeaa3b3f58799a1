"""Surprise at the robot said after a comma, with its reason (round 32): "wander up to the robot,
surprised to see it at a gig", "edge towards it, amazed to find one at a wedding", "stop by the robot,
startled to spot it during the show". Whatever the group does about the robot, the feeling says how:
Surprised. The occasion said with it ("at a gig", "at the match", "during the show") is an event, not a
place the world lacks."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading

_SURPRISE = ("surprised|amazed|astonished|astounded|startled|stunned|shocked|flabbergasted|gobsmacked|"
             "dumbfounded|bemused|taken\\s+aback")
_FEELING = re.compile(r",\s*(?:(?:quite|very|rather|so|a\s+bit|a\s+little|clearly|visibly|utterly|totally|"
                      r"pleasantly|genuinely)\s+)?(?:" + _SURPRISE + r")\s+(?:to\s+(?:see|find|spot|meet|"
                      r"come\s+across|run\s+into|bump\s+into|catch\s+sight\s+of)|by|at)\b", re.I)
EVENTS = frozenset("gig gigs concert concerts wedding weddings match matches game games show shows party parties "
                   "funeral funerals christening christenings festival festivals gala galas ceremony ceremonies "
                   "performance performances recital recitals premiere premieres screening screenings tournament "
                   "tournaments fixture fixtures derby disco rave ball prom graduation reunion "
                   "do dos bash bashes".split())
_OCCASION = re.compile(r"\b(?:at|during|in\s+the\s+middle\s+of|mid-?)\s*(?:a|an|the|this|their|our|his|her)\s+"
                       r"(?:[\w'-]+\s+)?([\w'-]+)", re.I)


def surprised_at(prompt: str, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """Groups that react to the robot with surprise said after a comma react Surprised."""
    return tuple(replace(g, robot_reaction="Surprised")
                 if g.robot_interaction in ("approach", "look", "follow") and _FEELING.search(g.text or prompt)
                 else g for g in groups)


def occasions(prompt: str) -> frozenset[str]:
    """The events a surprise is had at ("surprised to see it at a gig": gig), not places."""
    if not _FEELING.search(prompt):
        return frozenset()
    return frozenset(m.group(1).lower() for m in _OCCASION.finditer(prompt) if m.group(1).lower() in EVENTS)
