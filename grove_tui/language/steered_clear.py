"""Avoiding the robot by steering something wide of it, or by holding back from it (round 30): "swerves
her buggy wide of the robot", "steers his trolley well clear of it", "wheels the pram round the robot at
a distance", "hangs back from the robot", "hangs back as the robot passes". The small parser reads the
thing steered as the verb's object and finds no reaction; the person avoids the robot (Scared).
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading

_ROBOT = r"(?:the\s+(?:\w+\s+)?(?:robot|droid|bot)|it)\b"
_STEER = (r"\b(?:swerv|steer|veer|wheel|push|guid|nudg|manoeuvr|maneuver|edg|angl|jink|swing|swung|tak|took)"
          r"\w*\s+(?:(?:her|his|their|its|the|a|an|my|our|your)\s+)?(?:[\w-]+\s+){0,2}?")
_WIDE = r"(?:(?:well|way|very|good\s+and)\s+)?(?:wide|clear)\s+of\s+"
_STEERED = re.compile(_STEER + _WIDE + _ROBOT, re.I)
_HANG_BACK = re.compile(r"\b(?:hang|hangs|hanging|hung|hold|holds|holding|held|stay|stays|staying|stayed|keep|keeps|"
                        r"keeping|kept)\s+(?:well\s+)?back\s+(?:from\s+" + _ROBOT + r"|(?:as|while|when|until)\s+"
                        + _ROBOT + r")", re.I)


def steers_clear(text: str) -> bool:
    """Whether a group's words steer something wide of the robot or hang back from it."""
    return bool(_STEERED.search(text) or _HANG_BACK.search(text))


def steering_clear_of_the_robot(groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """Groups that steer wide of the robot or hang back from it avoid it; a reaction already read stays."""
    out: list[GroupReading] = []
    for g in groups:
        if g.robot_interaction is None and g.intent in ("wait", "walk", "wander") and steers_clear(g.text):
            g = replace(g, intent="robot", robot_interaction="avoid", robot_reaction="Scared")
        out.append(g)
    return tuple(out)
