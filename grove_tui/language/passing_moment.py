"""A reaction tied to the moment the robot passes: "a guide looks up as the robot passes the desk", "two
cleaners glance at the robot as it goes by", "visitors turn when the robot drives past them".

The reading keeps the group's own words (GroupReading.text: "A guide looks up") and the robot's clause
apart ("the robot passes the desk", its via the desk); the "as / when / while" that ties the two is in
neither. This reads it from the sentence: whether the words right after the group's text say the look
happens as the robot passes, and which place it passes there (the robot's via, when its clause is that one).

    passing_moment(prompt, group, robot)  # None, or a PassingMoment (place: the place passed, or None)
    with_passing_moments(prompt, reading)  # the reading with each reacting group's moment in its fields
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace

from grove_tui.language.model import GroupReading, PromptReading, RobotReading

_WHEN = r"(?:as|when|while|whenever|once|each\s+time|every\s+time|the\s+moment|just\s+as)"
_WHO = r"(?:the\s+robot|it|the\s+machine|the\s+droid)"
_PASS = (r"(?:pass(?:es|ed)?(?:\s+by)?|(?:goes|went|drives|drove|rolls|rolled|glides|glided|comes|came|moves|moved)"
         r"\s+(?:by|past))")
_MOMENT = re.compile(rf"^\s*,?\s*{_WHEN}\s+(?P<clause>{_WHO}\s+{_PASS}\b[^,.;]*)", re.IGNORECASE)


@dataclass(frozen=True)
class PassingMoment:
    place: str | None  # the place the robot passes then ("the desk": information_desk); None: them


def passing_moment(prompt: str, group: GroupReading, robot: RobotReading | None) -> PassingMoment | None:
    """The moment a group's reaction is tied to: the robot passing (a place, or them); None when the
    sentence ties it to no such moment."""
    text = (group.text or "").strip()
    if not text:
        return None
    at = prompt.lower().find(text.lower())
    if at < 0:
        return None
    found = _MOMENT.match(prompt[at + len(text):])
    if found is None:
        return None
    clause = " ".join(found.group("clause").lower().split())
    said = " ".join((robot.text if robot is not None else "").lower().split())
    place = None
    if robot is not None and robot.via and said and clause.startswith(said):
        place = robot.via[0]  # "as the robot passes the desk": the robot's clause is this one, its via the desk
    return PassingMoment(place)


def with_passing_moments(prompt: str, reading: PromptReading) -> PromptReading:
    """`reading` with the groups whose reaction is tied to the robot passing marked so (reacts_as_robot_passes,
    passed_place): read here, from the sentence, so planning never reads the sentence again."""
    groups = []
    for g in reading.groups:
        moment = passing_moment(prompt, g, reading.robot) if g.robot_interaction is not None else None
        groups.append(g if moment is None else replace(g, reacts_as_robot_passes=True, passed_place=moment.place))
    return replace(reading, groups=tuple(groups))
