"""The owner of the robot's place, who stays in it (round 36): "the robot ferries the post from Mrs
Whitfield's office to the cash office; she stays put in hers", "the robot takes the minutes to Ms
Adeyemi's office, where she waits". The owner is read as a person of the scene from the robot's own
place phrase, and her own later clause ("she stays put in hers") names her place only by a pronoun;
she stays in the place of the robot's route that is hers."""

from __future__ import annotations

import re
from dataclasses import replace

from grove_tui.language.model import GroupReading, PromptReading

_STAYS = re.compile(r"\b(?:she|he|they)\s+(?:\w+\s+){0,2}?(?:stays|stay|remains|remain|waits|wait|sits|sit|"
                    r"stops|stop|works|work|is|are)\b[^.;!?]*?\b(?:hers|his|theirs|there|in\s+it)\b"
                    r"|\bwhere\s+(?:she|he|they)\s+(?:\w+\s+)?(?:stays|stay|remains|remain|waits|wait|sits|sit|"
                    r"works|work|is|are)\b", re.IGNORECASE)


def _owned_place(text: str, who: str, reading: PromptReading) -> str | None:
    """The robot's start or destination said as `who`'s place ("from Mrs Whitfield's office"), else None."""
    robot = reading.robot
    if robot is None:
        return None
    owned = re.search(rf"\b(?P<prep>from|to|into|towards|toward|out\s+of)\s+{re.escape(who)}(?:'s|')\s",
                      text, re.IGNORECASE)
    if owned is None or _STAYS.search(text, owned.end()) is None:
        return None
    return robot.start if owned.group("prep").lower() in ("from", "out of") else robot.destination


def owners_stay_put(text: str, reading: PromptReading) -> PromptReading:
    """The reading with the owner of the robot's place, said to stay, at that place (module doc)."""
    groups: list[GroupReading] = []
    for g in reading.groups:
        if g.intent == "wait" and g.count.value == 1 and not (g.location or g.start or g.destination or g.via):
            place = _owned_place(text, g.who, reading)
            if place is not None:
                g = replace(g, location=place)
        groups.append(g)
    return replace(reading, groups=tuple(groups))
