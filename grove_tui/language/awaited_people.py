"""The people a robot waits for, at the place of what they do (issue 29): "the robot waits for twelve
commuters to board the train at platform 1", "the robot waits for three nurses to leave the lift by the
main entrance". The robot's clause runs to the sentence's end, so the place said after the waited-for
people's infinitive was the robot's alone and they had none. The place belongs to what they do: a group
named between "waits for" and that "to", with no place of its own, is there too (it stays there for a
stationary intent, else goes there). A place said before "for" ("waits by the door for the porters to
come") is the robot's only."""

from __future__ import annotations

import re
from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.model import PromptReading

_AWAITED = re.compile(r"\bwait(?:s|ing|ed)?\s+(?:\w+ly\s+)?for\s+(?P<who>[^,;.]+?)\s+to\s+(?P<rest>[^,;]+)$",
                      re.IGNORECASE)
_PLACE_PREPOSITIONS = re.compile(r"\b(?:at|on|in|by|near|beside|outside|inside|onto|into)\b", re.IGNORECASE)


def awaited_at_the_place(reading: PromptReading) -> PromptReading:
    """The reading, each group a waiting robot waits for at the place of what that group does (module doc)."""
    robot = reading.robot
    if robot is None or robot.task != "wait" or robot.location is None:
        return reading
    said = _AWAITED.search(robot.text.strip().rstrip(".!"))
    if said is None or not _PLACE_PREPOSITIONS.search(said.group("rest")):
        return reading
    awaited = f" {said.group('who').lower()} "
    groups = list(reading.groups)
    for n, g in enumerate(groups):
        if g.start or g.destination or g.location or g.via or not g.who or f" {g.who.lower()} " not in awaited:
            continue
        stays = g.intent in lx.STATIONARY_INTENTS
        groups[n] = replace(g, location=robot.location) if stays else replace(g, destination=robot.location)
    return replace(reading, groups=tuple(groups))
