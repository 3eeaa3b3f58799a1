"""Coming over to the robot after seeing it (round 37): "spot the robot by the turntable and hurry
across, dying to see what it does", "see the robot and rush over, eager to find out what it is", "catch
sight of it and dash across to get a closer look". Seeing the robot reads a look; coming over, with no
place to go to but the robot, goes further: approaching it (Curious).

So does coming over in order to look at it (round 44): "drift across to get a proper squint at the robot",
"wander over for a closer look at it", "come over to peer at the robot". A look with no going over
("stop to look at the robot", "twist round to peer at it") stays a look."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.model import GroupReading
from grove_tui.language.tokens import verb_lemma

# Verbs of hurrying that the walking lists may lack ("scamper", "dash", "bound").
_HURRYING = frozenset("run rush hurry dash race scamper scurry scuttle trot toddle jog sprint bound skip hop "
                      "stride march wander stroll amble saunter mosey sidle come waddle totter shuffle hare "
                      "zip zoom nip pop".split())
_COMING_OVER = re.compile(
    r"\b(?:robot|it)\b[^,.;:!?]*?\b(?:and|then|before)\s+(?:then\s+|quickly\s+|promptly\s+|eagerly\s+|excitedly\s+)?"
    r"([a-z]+)\s+(?:straight\s+|right\s+)?(?:over|across|up)\b"
    r"(?=\s*(?:$|[,.;!]|and\b|to\s+(?:it\b|the\s+robot\b|(?!the\b|a\b|an\b|his\b|her\b|their\b|its\b)[a-z]+\b)))", re.I)


# Going over to look at the robot: a verb of going, a word of direction, then a look at it as the purpose.
_LOOKS = r"(?:look|squint|peek|peep|gander|glance|nose|nosey|butcher's|gawp|gawk|view|see)"
_COMING_TO_LOOK = re.compile(
    r"\b([a-z]+)\s+(?:straight\s+|right\s+)?(?:over|across|up|closer|nearer)\s+"
    r"(?:(?:to\s+(?:get|have|take|grab|steal|sneak|catch)\s+(?:a|an)\s+(?:[a-z]+\s+){0,2}" + _LOOKS + r")|"
    r"(?:for\s+(?:a|an)\s+(?:[a-z]+\s+){0,2}" + _LOOKS + r")|(?:to\s+(?:look|peer|gaze|stare|gawp|gawk|peek|squint|"
    r"marvel|gape)))\s+at\s+(?:the\s+|our\s+|this\s+|that\s+)?(?:robot|it)\b", re.I)


def _going_by(pattern: re.Pattern[str], text: str) -> bool:
    """Whether the pattern finds a verb of going (walking, wandering or hurrying) in the text."""
    m = pattern.search(text)
    if m is None:
        return False
    v = verb_lemma(m.group(1))
    return v in _HURRYING or lx.INTENT_VERBS.get(v) in ("walk", "wander")


def _comes_to_look(text: str) -> bool:
    return _going_by(_COMING_TO_LOOK, text)


def _comes_over(text: str) -> bool:
    return _going_by(_COMING_OVER, text)


def coming_over_after_seeing(prompt: str, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """The groups that look at the robot and then come over to it, read as approaching it."""
    reacting = [g for g in groups if g.robot_interaction is not None]
    return tuple(replace(g, robot_interaction="approach", robot_reaction="Curious")
                 if g.robot_interaction == "look" and (
                     g.robot_reaction == "Surprised" and _comes_over(g.text or (prompt if reacting == [g] else ""))
                     or _comes_to_look(g.text or (prompt if reacting == [g] else ""))) else g for g in groups)
