"""Following the robot said by "dog" (round 37): "two graduates dog the robot's steps across the floor",
"a visitor dogs the robot through the waiting room", "dogging its every move". The parser takes "dog"
for the animal, so the clause finds no reaction; read on the group's own words, it is following the
robot (Curious). "Dog" in a compound ("the dog-sitter", "dog walkers") or after a determiner is the
animal and is left alone."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading

_DOGGING = re.compile(r"(?<![\w-])(?<!\bthe\s)(?<!\ba\s)(?<!\bhis\s)(?<!\bher\s)(?<!\btheir\s)(?<!\bour\s)"
                      r"(?:dog|dogs|dogged|dogging)\s+(?:(?:the|our|this|that|its)\s+(?:[\w-]+\s+)?robot|it)\b"
                      r"(?!\s*-)", re.I)


def dogging_the_robot(groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """The groups that dog the robot, with no reaction read, read as following it."""
    return tuple(replace(g, intent="robot", robot_interaction="follow", robot_reaction="Curious", destination=None)
                 if g.robot_interaction is None and _DOGGING.search(g.text) else g for g in groups)
