"""The robot's errand: what it picks up where and drops off where, from its clause and its reading.

"The robot carries books from the returns desk to the reading room": the desk is where it picks them up
(it goes there first and stops a moment), the reading room where it drops them off. The reader gives the
places as the clause's start and destination ("fetches a map from the cloakroom" gives the cloakroom as a
place it passes); this pass names their roles:

- carry, bring, take, ferry, haul ... X from A to B: pick up at A, drop off at B;
- fetch, collect, pick up, get X from A (to B): pick up at A, drop off at B, else back where it set off;
- deliver X to B (from A): drop off at B, after picking up at A when said.

A clause without such a verb, or with none of its places, is no errand (None).
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from grove_tui.language.model import RobotReading

# a word after the verb that is no object: "moves to the door", "gets through the crowd"
_NO_OBJECT = "from|to|into|across|through|back|along|over|around|round|past|towards?|down|up|out|in|on|off|" \
    "away|slowly|quickly|carefully|itself|its way|between|via|the way|the long way|a shortcut|the lift|" \
    "the stairs|the elevator|the corridor"
_CARRY = re.compile(r"\b(?:carr(?:y|ies|ying)|brings?|bringing|takes?|taking|ferr(?:y|ies|ying)|hauls?|hauling|"
                    r"transports?|transporting|moves?|moving|wheels?|wheeling|pushes|pushing)\b"
                    r"(?= (?!(?:%s)\b)[a-z])" % _NO_OBJECT, re.I)
_FETCH = re.compile(r"\b(?:fetch(?:es|ing)?|collect(?:s|ing)?|picks? up|picking up|gets?|getting|retrieves?|"
                    r"retrieving)\b(?= (?!(?:%s)\b)[a-z])" % _NO_OBJECT, re.I)
_DELIVER = re.compile(r"\b(?:deliver(?:s|ing)?|drops? off|dropping off)\b", re.I)
_FROM = re.compile(r"\bfrom\b", re.I)
_TO = re.compile(r"\b(?:to|into|over to|up to)\b", re.I)


@dataclass(frozen=True)
class RobotErrand:
    """`pickup`: where it picks the thing up (a world place), None when it has it already; `dropoff`:
    where it leaves it, None for back where it set off (a fetch)."""

    kind: str  # "carry", "fetch" or "deliver"
    pickup: str | None
    dropoff: str | None


def robot_errand(robot: RobotReading | None) -> RobotErrand | None:
    """The robot's errand, when its clause asks one of a "cross" robot (module doc)."""
    if robot is None or robot.task != "cross" or robot.guides or robot.passes:
        return None
    text = robot.text
    said_from = _FROM.search(text) is not None
    from_place = robot.start or (robot.via[0] if robot.via and said_from else None)
    if _DELIVER.search(text):
        if robot.destination is None:
            return None
        return RobotErrand("deliver", from_place if said_from else None, robot.destination)
    if _FETCH.search(text):
        if from_place is None or not said_from:
            return None
        return RobotErrand("fetch", from_place, robot.destination if _TO.search(text) else None)
    if _CARRY.search(text):
        # "takes the lift to the first floor", "moves to the door": a carry names both ends
        if from_place is None or robot.destination is None or not said_from:
            return None
        return RobotErrand("carry", from_place, robot.destination)
    return None
