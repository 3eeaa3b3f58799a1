"""Going off to hide after seeing the robot (round 44): "a little girl sees the robot and scurries off to
hide", "a page boy is startled by the robot and runs off to hide behind the bar". Seeing the robot reads a
look; going off, away or back to hide from it goes further: avoiding it (Scared). Hiding where one is ("waves
to the robot and then hides behind her mum": shy, not fleeing) stays a look, and a hiding with no robot
named before it in the clause is left to the idioms of a clause the robot times (robot_idioms.py)."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading

_HIDING = re.compile(
    r"\b(?:robot|it)\b[^,.;:!?]*?\b(?:and|then|before)\s+(?:then\s+|promptly\s+|quickly\s+|immediately\s+)?"
    r"[a-z]+\s+(?:straight\s+)?(?:off|away|back)\s+to\s+(?:go\s+and\s+)?hide\b", re.I)


def hiding_after_seeing(groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """The groups that look at the robot and then go off to hide, read as avoiding it."""
    return tuple(replace(g, robot_interaction="avoid", robot_reaction="Scared")
                 if g.robot_interaction == "look" and _HIDING.search(g.text) else g for g in groups)
