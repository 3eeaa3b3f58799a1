"""The robot's clause typed as chat (round 18), written out before the prompt is parsed: "robo go 2
gate b1", "rbt waits by pharmacy" (short names of the robot), "robot shd wait @ cloakroom" (chat's
"should"), "bot to follow em" (a robot "to" do something: what it should do; "em" is "them"). Round 45: the robot
before a route drawn with an arrow ("bot kitchen -> reception", "robot: lobby → lifts") goes that way;
the arrow alone was read as a route of the robot's words), and the robot before a bare "-ing" verb ("bot
doing its rounds", "robot patrolling") is doing it: "is" is written in.)"""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.robot_on_patrol import on_patrol
from grove_tui.language.tokens import verb_lemma

# Short names of the robot in chat (whole words, any case).
_ROBOT_NAMES = re.compile(r"(?<![\w'@&/-])(robo|rbt|robt|robit|rbot|robott)(?![\w'@&/-])", re.IGNORECASE)
# Chat's "should" and "must" right after the robot: "robot shd wait", "bot shld follow".
_SHOULD = re.compile(r"(?<![\w'-])(robot|bot)(\s+)(shd|shld|shud|shuld|sld|shoud)(?![\w'-])", re.IGNORECASE)
# "bot to follow em": at the start of the text or of a clause, the robot "to" a verb of its tasks.
_ROBOT_TO = re.compile(r"(^|[,;:.!?]\s*|\b(?:and|n|then|&)\s+)((?:the\s+)?(?:robot|bot))(\s+)to(\s+)([A-Za-z]+)",
                       re.IGNORECASE)
# "bot kitchen -> reception": the robot, then a short place and an arrow, at a clause's start.
_ROBOT_ARROW = re.compile(r"(^|[,;:.!?]\s*|\b(?:and|n|then|&)\s+)((?:the\s+)?(?:robot|bot))\s*:?\s+(?:from\s+)?"
                          r"(?!(?:to|is|goes|will|should|then)\b)((?:[\w'-]+\s+){0,3}?[\w'-]+)\s*(?:-+>|→|⟶|=>)\s*",
                          re.IGNORECASE)
# "bot doing its rounds": the robot, then an "-ing" verb with no "is", at a clause's start.
_ROBOT_ING = re.compile(r"(^|[,;:.!?]\s*|\b(?:and|n|then|&)\s+)((?:the\s+)?(?:robot|bot))\s+(?=[a-z]{2,}ing\b)",
                        re.IGNORECASE)
_ROBOT_TASK_VERBS = (lx.ROBOT_WAIT_VERBS | lx.ROBOT_PATROL_VERBS | lx.ROBOT_FOLLOW_VERBS | lx.ROBOT_CROSS_VERBS
                     | lx.LEADING_VERBS | frozenset({"stay", "stand", "park", "hang"}))
# "em" for "them" after a verb: "follow em", "take em to the exit".
_EM = re.compile(r"(?<![\w'-])([A-Za-z]+)(\s+)'?em(?![\w'-])")


def robot_chat(text: str) -> str:
    """The text with the robot's chat written out (see the module doc)."""
    text = on_patrol(_ROBOT_NAMES.sub("robot", text))  # "bot on patrol along X": it patrols there
    text = _SHOULD.sub(lambda m: f"{m.group(1)}{m.group(2)}should", text)
    text = _ROBOT_TO.sub(_should_do, text)
    text = _ROBOT_ARROW.sub(lambda m: f"{m.group(1)}{m.group(2)} goes from {m.group(3)} to ", text)
    text = _ROBOT_ING.sub(lambda m: f"{m.group(1)}{m.group(2)} is ", text)
    return _EM.sub(_them, text)


def _should_do(m: re.Match[str]) -> str:
    if verb_lemma(m.group(5).lower()) not in _ROBOT_TASK_VERBS:
        return m.group(0)  # "the robot to the lifts" is no task of its own here
    return f"{m.group(1)}{m.group(2)}{m.group(3)}should{m.group(4)}{m.group(5)}"


def _them(m: re.Match[str]) -> str:
    verb = verb_lemma(m.group(1).lower())
    if verb not in _ROBOT_TASK_VERBS and verb not in lx.INTENT_VERBS and verb not in lx.ROBOT_VERBS:
        return m.group(0)
    return f"{m.group(1)}{m.group(2)}them"
