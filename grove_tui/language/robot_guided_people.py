"""People said first, then taken somewhere by the robot in a clause of its own that points back at
them: "A muddled old gentleman has wandered into the baggage hall, so the robot guides him back to
check-in", "Two lost tourists stand by the lifts and the robot escorts them to the exit". As when the
robot's clause names them ("the robot escorts a lost child to ..."), they follow the robot: from where
the sentence has them by then (where they stand, or where they wandered to) to where the robot takes
them, and the robot starts there. A clause of time ("waits at the desk until the robot leads her ...") keeps their wait, and a robot
whose clause gives no place of its own goes their way instead (language/guided_route.py)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading, RobotReading
from grove_tui.language.sentence import Sentence

_TIME_WORDS = frozenset({"until", "till", "til", "while", "before", "when", "whilst"})
_OWN_WAY = frozenset({"wait", "walk", "wander"})


def following_the_robot(s: Sentence, robot: RobotReading | None, first_robot_word: int,
                        read: Sequence[GroupReading]) -> tuple[RobotReading | None, tuple[GroupReading, ...]]:
    """The robot and the groups, the one the robot's later clause takes along following the robot from
    where it is, the robot starting there when its clause says no start (module doc)."""
    if robot is None or robot.task != "cross" or robot.guides is None or robot.destination is None or \
            any(s.low[k] in _TIME_WORDS for k in range(max(0, first_robot_word - 3), first_robot_word)):
        return robot, tuple(read)
    out = list(read)
    k = next((k for k, g in enumerate(out) if g.who == robot.guides), None)
    if k is None:
        return robot, tuple(read)
    g = out[k]
    if g.robot_interaction is not None or g.intent not in _OWN_WAY or g.destination == robot.destination or \
            g.text and g.text in robot.text:
        return robot, tuple(read)  # the robot's own object, already read as it says; or going there anyway
    where = g.location or g.destination or g.start
    out[k] = replace(g, intent="robot", robot_interaction="follow", robot_reaction="Curious", start=where,
                     destination=robot.destination, location=None, via=tuple(robot.via), wait_seconds=None)
    return (replace(robot, start=robot.start or where), tuple(out))
