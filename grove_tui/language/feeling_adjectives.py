"""A feeling said by an adjective set apart from the clause (round 30): "Spellbound, our toddler gawps at
the robot", "Intrigued, a lad stares at it", "Wary, an old man watches the robot", "A girl eyes the
robot, fascinated.", and between commas in the clause (round 44: "two sketchers lay aside their pencils,
fascinated, to study the robot"). Looking at the robot reads Surprised; the feeling says how they look: curious
(Curious) or afraid (Scared). Only a look is coloured so: a feeling never turns one interaction into
another.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading

_CURIOUS = frozenset("spellbound intrigued fascinated curious captivated enthralled mesmerised mesmerized "
                     "entranced enchanted inquisitive nosy nosey rapt agog beguiled transfixed".split())
_SCARED = frozenset("wary nervous scared frightened afraid fearful anxious uneasy apprehensive jumpy timid "
                    "terrified petrified spooked alarmed unnerved suspicious leery distrustful mistrustful "
                    "worried edgy twitchy skittish".split())
# Every word of feeling set apart from a clause (fronted_feelings.py: "Spellbound, a wee lad ..." is no name).
FEELINGS = _CURIOUS | _SCARED | frozenset("awestruck starstruck dumbstruck thunderstruck delighted thrilled "
                                          "excited amazed astonished astounded bewildered puzzled baffled "
                                          "perplexed gleeful giddy eager keen happy glad shy bashful "
                                          # anger and low moods: "Livid, an old man strides over ..." is no one
                                          # called Livid (angry_approach.py reads the threat from the prompt)
                                          "livid furious fuming irate enraged incensed seething angry outraged "
                                          "cross indignant exasperated grumpy impatient weary sleepy bored "
                                          "sad glum gloomy tearful upset".split())
_WORD = r"(?:(?:a\s+(?:little|bit)|rather|very|quite|slightly|clearly|visibly|utterly|totally|somewhat|"\
        r"a\s+touch)\s+)?([a-z]+)"
_FRONTED = re.compile(r"^\s*" + _WORD + r"\s*,", re.I)
_TRAILING = re.compile(r",\s*" + _WORD + r"\s*[.!]?\s*$", re.I)
_BETWEEN = re.compile(r",\s*" + _WORD + r"\s*,", re.I)


def said_feeling(prompt: str) -> str | None:
    """The reaction a feeling set apart at the start or the end of a one-clause prompt says."""
    found = [m.group(1).lower() for m in (_FRONTED.search(prompt), _TRAILING.search(prompt)) if m]
    found += [m.group(1).lower() for m in _BETWEEN.finditer(prompt)]
    for word in found:
        if word in _CURIOUS:
            return "Curious"
        if word in _SCARED:
            return "Scared"
    return None


def coloured_by_feeling(prompt: str, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """The one group that looks at the robot, with the reaction its set-apart feeling says."""
    feeling = said_feeling(prompt)
    lookers = [g for g in groups if g.robot_interaction == "look"]
    if feeling is None or len(lookers) != 1 or len(groups) != 1:
        return tuple(groups)
    return tuple(replace(g, robot_reaction=feeling) if g.robot_interaction == "look" else g for g in groups)
