"""The robot said again by another word for a machine (round 43): once a sentence has named the robot
(or robots at all), "the machine", "the contraption", "that gadget" with nothing before the noun is the
robot ("An old porter who distrusts robots sidesteps the machine in the corridor": the porter avoids
the robot), not a cash machine or a coffee machine the world has. Said as "the robot" for the reader."""

from __future__ import annotations

import re

_ROBOT_SAID = re.compile(r"\b(?:robots?|bots?|droids?)\b", re.IGNORECASE)
# "the machine", "that contraption", not "the machine room" nor "the machine's screen".
_ALIAS = re.compile(
    r"\b(the|that|this)\s+(machine|contraption|gadget|droid|automaton|android)\b"
    r"(?!\s*(?:'s|’s|-)|\s+(?:room|rooms|shop|hall|area|bay|floor|workshop|zone|store|section|aisle|line|lane|"
    r"park|yard|house|shed|corner|bank|wash|operator|learning|gun|guns|code|tool|tools)\b)", re.IGNORECASE)


# "our machine", "our delivery bot", "our little droid" (round 72): a machine the speaker owns in a scene
# is the robot even before the robot is named, not "our coffee machine" (a thing word before the noun is
# only taken when it says what the robot does).
_OWNED_ALIAS = re.compile(
    r"\bour\s+(?:(?:delivery|service|cleaning|security|patrol|little|trusty|friendly|new)\s+)?"
    r"(machine|contraption|gadget|droid|automaton|android|bot)\b"
    r"(?!\s*(?:'s|’s|-)|\s+(?:room|rooms|shop|hall|area|bay|floor|workshop|zone|store|section|aisle|line|lane|"
    r"park|yard|house|shed|corner|bank|wash|operator|learning|gun|guns|code|tool|tools)\b)", re.IGNORECASE)


def with_robot_aliases(text: str) -> str:
    """The text with each bare machine word after the robot's first mention said as "the robot", and
    the speaker's own machine ("our machine") said so anywhere."""
    text = _OWNED_ALIAS.sub("the robot", text)
    first = _ROBOT_SAID.search(text)
    if first is None:
        return text
    head, tail = text[:first.end()], text[first.end():]
    return head + _ALIAS.sub(lambda m: f"{m.group(1)} robot", tail)
