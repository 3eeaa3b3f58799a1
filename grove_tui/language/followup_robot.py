"""The robot in a follow-up: removed ("no robot", "remove the robot"), added back ("add a robot that
waits at reception"), or given a task by a clause whose subject is the robot ("the robot waits at
reception", "send the robot to the lifts", "put the robot at the entrance"). The task is read by the
reader as the same words said of the robot, else of one person (`RobotReading`: task, places).
"""

from __future__ import annotations

import re
from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.edits import RobotEdit
from grove_tui.language.followup_context import FollowupContext
from grove_tui.language.followup_phrases import DETERMINER_PATTERN, ROBOT_PATTERN
from grove_tui.language.model import RobotReading
from grove_tui.language.places import place_index
from grove_tui.language.tokens import lemma, words

_NO_ROBOT = re.compile(
    rf"^(?:(?:remove|delete|drop|lose|ditch|disable|get rid of|take (?:out|away)|switch off|turn off|forget|"
    rf"skip)\s+(?:{DETERMINER_PATTERN}\s+)?{ROBOT_PATTERN}|(?:no|without)(?:\s+(?:a|the|any))?\s+{ROBOT_PATTERN}"
    rf"|there (?:is|should be) no {ROBOT_PATTERN}|(?:we|i) (?:do not|don't|dont) (?:need|want) (?:a |the |any )?{ROBOT_PATTERN})\b")
_ADD_ROBOT = re.compile(
    rf"^(?:add|include|bring(?: in| back)?|put|place|also|plus|with|use|there is)\s+(?:(?:a|the|one|our|back)\s+)+"
    rf"{ROBOT_PATTERN}\b(?:\s+back)?\s*(?:(?:that|which|who)\s+)?(.*)$")
_ROBOT_SUBJECT = re.compile(rf"^(?:(?:make|let|have|get|tell|ask)\s+)?{DETERMINER_PATTERN}\s+{ROBOT_PATTERN}"
                            rf"\s+(.+)$")
# "send the robot to the lifts", "put the robot at the entrance": verb -> how the rest is read.
_MOVE_ROBOT = re.compile(rf"^(send|take|move|drive|steer|bring|put|place|position|start|park|station)\s+"
                         rf"{DETERMINER_PATTERN}\s+{ROBOT_PATTERN}\s+(.+)$")
_ROBOT_START = re.compile(r"^(?:(?:should|must|will|can)\s+)?(?:starts?|begins?|spawns?|comes? from|starting)\s+"
                          r"(?:off\s+)?(?:at|in|from|by|near|on)?\s*(.+)$")
_ROBOT_END = re.compile(r"^(?:(?:should|must|will|can)\s+)?(?:ends?|finish(?:es)?|stops?|arrives?)\s+"
                        r"(?:up\s+)?(?:at|in|by|near|on)\s+(.+)$")


def read_robot_edit(text: str, ctx: FollowupContext) -> RobotEdit | None:
    """The robot edit a clause states, else None (the clause is about people)."""
    if _NO_ROBOT.match(text):
        return RobotEdit("remove", text)
    m = _ADD_ROBOT.match(text)
    if m is not None:
        task = _robot_task(m.group(1), ctx) if m.group(1).strip() else None
        return RobotEdit("add", text, task)
    m = _MOVE_ROBOT.match(text)
    if m is not None:
        verb, rest = m.group(1), m.group(2)
        if verb in ("put", "place", "position", "start", "station"):
            rest = "starts " + rest
        elif verb == "park":
            rest = "waits " + rest
        else:
            rest = "goes " + rest
        return RobotEdit("set", text, _robot_task(rest, ctx))
    m = _ROBOT_SUBJECT.match(text)
    if m is not None and not re.search(rf"\b{ROBOT_PATTERN}\b", m.group(1)):
        return RobotEdit("set", text, _robot_task(m.group(1), ctx))
    return None


def _robot_task(predicate: str, ctx: FollowupContext) -> RobotReading | None:
    """What a predicate asks of the robot, read as the same words said of one person."""
    predicate = predicate.strip()
    start = _ROBOT_START.match(predicate)
    end = _ROBOT_END.match(predicate)
    if start is not None or end is not None:
        place = _place_of(((start or end).group(1)), ctx)  # type: ignore[union-attr]
        if place is None:
            ctx.notes.append(f"'{predicate}': no place of this world is named for the robot")
            return None
        return RobotReading("cross", start=place if start is not None else None,
                            destination=place if end is not None else None, text=predicate)
    said = ctx.read(f"the robot {predicate}")
    if said.robot is not None and not said.groups and not any(c.unsure for c in said.robot.confidence):
        ctx.note_unknown(said.unknown_places)
        return replace(said.robot, text=predicate)
    # the same words said of a person, read as the reader reads people
    reading = ctx.read(f"a person {predicate}")
    ctx.note_unknown(reading.unknown_places)
    if not reading.groups:
        ctx.notes.append(f"'{predicate}': nothing the robot can do was read")
        return None
    g = reading.groups[0]
    if g.intent in ("wait", "queue", "converse"):
        where = g.location or g.destination or g.start
        if where is None:
            ctx.notes.append(f"'{predicate}': the robot waits where it starts")
        return RobotReading("wait", start=where, location=where, text=predicate)
    if g.intent == "wander":
        return RobotReading("patrol", location=g.location or g.start, text=predicate)
    if g.intent == "follow":
        return RobotReading("follow", destination=g.destination, text=predicate)
    if not (g.start or g.destination or g.via):
        ctx.notes.append(f"'{predicate}': no place of this world is named for the robot")
        return None
    return RobotReading("cross", start=g.start, destination=g.destination, via=g.via, text=predicate)


def _place_of(phrase: str, ctx: FollowupContext) -> str | None:
    lemmas = [lemma(w) for w in words(phrase) if w not in lx.DETERMINERS]
    found = place_index(ctx.world).match(lemmas)
    return found.name if found is not None else None
