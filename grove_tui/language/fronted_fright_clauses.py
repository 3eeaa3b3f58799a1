"""A fright fronted with the robot's own clause before the subject (round 65): "Spooked as the robot
rolls up, a trio of kids scramble out of X", "Rattled when the robot beeps, two cleaners hurry off".
The clause says what the robot does, and the fronted word says how the subject takes it: fright, so
the subject avoids the robot, Scared, whatever verb of moving follows. A fright fronted with a cause
("Spooked by the robot, ...") is read by the lexicon's feelings; a group that already reacts otherwise
to the robot (looking, coming over) keeps its reading, and only its missing reaction is filled in."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.fronted_surprise import sentence_after
from grove_tui.language.model import GroupReading

_FRIGHTS = ("spooked|startled|rattled|frightened|scared|alarmed|unnerved|terrified|petrified|panicked|shaken|"
            "jumpy|nervous|uneasy|wary|fearful|afraid|panicky|jittery|freaked(?:\\s+out)?|put\\s+off")
_FRONTED = re.compile(r"(?:^|[.!?;]\s+)(?:(?:a\s+(?:bit|little)|rather|quite|slightly|badly|thoroughly|really)\s+)?"
                      rf"(?:{_FRIGHTS})\s+(?:as|when|while|once|the\s+(?:moment|instant|minute|second)|"
                      r"(?:just|as\s+soon)\s+as)\s+(?:the|a|our|its)\s+(?:[\w-]+\s+){0,2}?robot\b[^,.;!?]*,\s*",
                      re.I)
_MOVES_ON = frozenset({None, "avoid"})



def frightened_by_fronted_clause(prompt: str, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """The subject after a fronted fright with the robot's clause, avoiding it, Scared (module doc)."""
    out = list(groups)
    for m in _FRONTED.finditer(prompt):
        sentence = sentence_after(prompt, m.end()).lower()
        said = [k for k, g in enumerate(out) if g.text and g.text.lower() in sentence]
        if not said:
            continue
        k = min(said, key=lambda j: sentence.find((out[j].text or "").lower()))
        g = out[k]
        if g.robot_interaction not in _MOVES_ON:
            if g.robot_reaction is None:
                out[k] = replace(g, robot_reaction="Scared")
            continue
        out[k] = replace(g, intent="robot", robot_interaction="avoid", robot_reaction=g.robot_reaction or "Scared")
    return tuple(out)
