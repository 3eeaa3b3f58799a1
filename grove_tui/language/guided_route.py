"""The route of a robot that guides people its clause gives no place of its own: "ten passengers at gate
B1 walk to the exit while the robot guides them", "the visitors head for the café and the robot leads
the way with them". The robot goes where the people it guides go, from where they start: their route
is its route, and the people it guides are named by their own words so the plan and the report find
them. With no route for them either, the sentence sets the robot none (no reading)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.mention import Mention
from grove_tui.language.model import GroupReading, RobotReading
from grove_tui.language.tokens import lemma

_POINTING = frozenset({"them", "him", "her", "us", "everyone", "everybody"})
_SINGULAR = frozenset({"him", "her"})
_ROUTE_FIELDS = ("start", "destination", "via", "location")


def route_from_the_guided(robot: RobotReading | None, first_robot_word: int, mentions: Sequence[Mention],
                          read: Sequence[GroupReading]) -> RobotReading | None:
    """`robot` with the route of the group it guides when its own clause gave none; None when that
    group goes nowhere said; `robot` unchanged otherwise."""
    if robot is None or robot.task != "cross" or robot.guides is None or \
            robot.start or robot.destination or robot.via:
        return robot
    group = _guided(robot.guides, first_robot_word, mentions, read)
    if group is None or not (group.destination or group.via):
        return None  # "a child waits while the robot guides her": no way to go is said
    start = group.start or (group.location if group.location != group.destination else None)
    confidence = tuple(c for c in group.confidence if c.field in _ROUTE_FIELDS)
    return replace(robot, start=start, destination=group.destination, via=tuple(group.via), guides=group.who,
                   confidence=confidence)


def _guided(guides: str, first_robot_word: int, mentions: Sequence[Mention],
            read: Sequence[GroupReading]) -> GroupReading | None:
    """The group the robot's words name, else for a pronoun the group said last before its clause
    (one person for "him", "her")."""
    words = guides.lower().split()
    named = {lemma(w) for w in words} - _POINTING - {"a", "an", "the", "all", "of"}
    if named:
        return next((g for g in read if named & {lemma(w) for w in g.who.lower().split()}), None)
    if not words or words[-1] not in _POINTING:
        return None
    singular = words[-1] in _SINGULAR
    whos = {g.who: g for g in read}
    for m in reversed([m for m in mentions if m.last < first_robot_word]):
        group = whos.get(m.who)
        if group is not None and (not singular or group.count.value == 1):
            return group
    return None
