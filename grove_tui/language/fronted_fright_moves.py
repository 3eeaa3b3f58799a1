"""A feeling fronted before its subject, and the subject moving away from the robot or coming over to it
(round 72): "Petrified, a small lad crouches behind the display cases once the robot rolls up",
"Rattled by the robot, a pensioner edges off sideways", "Flustered when it beeps at her heels, a
shopper shrinks back from the robot", "Startled by the robot reversing, a porter hastily backs off":
a fright (or a start) and a move away from it, so the subject avoids the robot, Scared. A start
that only steps back ("Startled by the robot, a woman steps back") is left a look, and a bare
"Startled," whose subject only leaps back is surprise (`fronted_surprise.py`); hiding or backing off
is fright. "Fascinated, two visitors wander across to study the robot": curiosity that walks over to
it approaches it, Curious."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading
from grove_tui.language.robot_aliases import with_robot_aliases

_FRIGHTS = ("spooked|startled|rattled|flustered|frightened|scared|alarmed|unnerved|terrified|petrified|panicked|"
            "shaken|jumpy|nervous|uneasy|fearful|afraid|panicky|jittery|freaked(?:\\s+out)?|frazzled|flummoxed")
_CURIOUS = "fascinated|intrigued|curious|enthralled|captivated|spellbound|mesmerised|mesmerized|entranced"
_DEGREE = r"(?:(?:a\s+(?:bit|little)|rather|quite|slightly|badly|thoroughly|really|utterly|completely)\s+)?"
# The fronted word, alone or with its cause or its moment ("by the robot ...", "when it beeps ..."), to
# the comma before the subject.
_FRONTED = re.compile(rf"(?:^|[.!?;]\s+){_DEGREE}(?P<feel>{_FRIGHTS}|{_CURIOUS})"
                      r"(?:\s+(?:by|at|when|as|while|once|after)\b[^,.;!?]*)?\s*,\s*", re.I)
_AWAY = re.compile(
    r"\b(?:back(?:s|ed)|back(?=\s+(?:off|away))|backing|edges?|edging|shrinks?|shrinking|scuttles?|scuttling|scurr(?:y|ies|ying)|"
    r"scrambles?|scrambling|shuffles?|shuffling|sidles?|sidling|creeps?|creeping|slinks?|slinking|"
    r"retreats?|retreating|recoils?|recoiling|cowers?|cowering|hides?|hiding|ducks?|ducking|"
    r"crouch(?:es)?|crouching|shies|shying)\b"
    r"(?:\s+\w+ly)?\s*(?:off|away|back|behind|sideways|out\s+of\s+(?:its|the)\s+way|$|[,.;!?])", re.I)
_OVER = re.compile(r"\b(?:wander|amble|stroll|drift|head|come|go|walk|saunter|mosey|pad|trot|edge|creep|sidle)"
                   r"(?:s|ed|ing)?\s+(?:across|over|up)\b[^,.;!?]*\b(?:the\s+robot|it)\b", re.I)
_ROBOT = re.compile(r"\b(?:the\s+robot|it)\b", re.I)
_SETTLED_CURIOUS = frozenset({"approach", "follow"})


def _sentence_after(prompt: str, start: int) -> str:
    """The rest of the sentence from `start`, a stop after a lone capital ("the T. rex") not its end."""
    end = re.search(r"(?<![\s.][A-Z])[.!?;](?:\s|$)", prompt[start:])
    return prompt[start:start + end.start()] if end else prompt[start:]


def _words(g: GroupReading) -> str:
    """How the group is said ("a small lad"), lower case."""
    return (g.who or g.text or "").lower()


def feeling_moves_fronted(prompt: str, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """The subject after a fronted feeling who moves away from the robot (Scared) or over to it (Curious)."""
    out = list(groups)
    prompt = with_robot_aliases(prompt)  # "once our machine rolls up": the robot
    for m in _FRONTED.finditer(prompt):
        sentence = _sentence_after(prompt, m.end())
        if not _ROBOT.search(prompt[m.start():m.end()] + " " + sentence):
            continue
        low = sentence.lower()
        said = [k for k, g in enumerate(out) if _words(g) and _words(g) in low]
        if not said and m.start() == 0 and out:
            said = [0]  # the subject said otherwise by the reader ("a nine-year-old": a child)
        if not said:
            continue
        k = min(said, key=lambda j: low.find(_words(out[j])))
        g = out[k]
        curious = re.fullmatch(_CURIOUS, m.group("feel"), re.I) is not None
        if not curious and _AWAY.search(sentence) and g.robot_interaction in (None, "look", "avoid"):
            out[k] = replace(g, intent="robot", robot_interaction="avoid", robot_reaction="Scared")
        elif curious and _OVER.search(sentence) and g.robot_interaction not in _SETTLED_CURIOUS:
            if g.robot_interaction in (None, "look"):
                out[k] = replace(g, intent="robot", robot_interaction="approach",
                                 robot_reaction=g.robot_reaction or "Curious")
    return tuple(out)
