"""The robot does not follow people who follow it: it leads them.

"The robot accompanies a patient to radiology" is read as both "the robot follows a patient" (the robot's
clause) and "a patient follows the robot" (the patient's). Planned as read, each followed the other, and
the report claimed one asked behaviour twice with opposite roles: a robot_follow claim for the patient
and a robot_follow_person claim for the robot. When the person a robot's "follow" names is a group that
itself follows the robot, the robot leads them (a "cross" that guides them, to the place they go), and
the one claim is theirs: that they went with it.
"""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language.model import PromptReading
from grove_tui.language.tokens import lemma, words

_NOT_A_NAME = frozenset({"a", "an", "the", "one", "some", "of", "group", "him", "her", "them", "someone"})


def leads_who_follow_it(reading: PromptReading) -> PromptReading:
    """The reading with a robot that "follows" people who follow it made to lead them (module doc)."""
    robot = reading.robot
    if robot is None or robot.task != "follow" or not robot.follows:
        return reading
    named = {lemma(w) for w in words(robot.follows.lower())} - _NOT_A_NAME
    pronoun = not named
    followers = [g for g in reading.groups if g.robot_interaction == "follow"]
    match = next((g for g in followers if named & ({lemma(w) for w in words(g.who.lower())} | {lemma(g.label)})),
                 followers[0] if pronoun and len(followers) == 1 else None)
    if match is None:
        return reading
    led = replace(robot, task="cross", follows=None, guides=match.who,
                  destination=robot.destination or match.destination, start=robot.start or match.start)
    return replace(reading, robot=led)
