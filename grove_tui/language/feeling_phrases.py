"""A feeling about the robot said outright in a phrase (round 37): "gapes at the robot, then starts
howling in fright", "stares at it, trembling with fear", "eyes the robot in alarm" (Scared, though
looking reads Surprised); "Taken aback at finding the robot by his wardrobe, the son edges away", "steps
aside in astonishment" (Surprised, though shrinking away reads Scared). The feeling said wins over the
verb's own; it never turns one interaction into another. "Startled" and "shocked" are left to the verb:
a start may be fright or surprise."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading

_FRIGHT = re.compile(r"\b(?:in|with|from|out\s+of)\s+(?:sheer\s+|pure\s+|utter\s+|abject\s+|a\s+)?(?:fright|terror|fear|"
                     r"alarm|panic|horror|dread|trepidation)\b|\b(?:scared|frightened|terrified)\s+(?:stiff|witless|"
                     r"out\s+of\s+\w+\s+wits)\b|\b(?:terrified|petrified|frightened|scared|panicked|panicking)\b",
                     re.I)
_SURPRISE = re.compile(r"\btaken\s+aback\b|\bcaught\s+off[\s-]+(?:his|her|their|its)?\s*guard\b|\bin\s+(?:sheer\s+|"
                       r"utter\s+|complete\s+|open-mouthed\s+)?(?:surprise|astonishment|amazement|disbelief|wonder)\b|"
                       r"\b(?:astonished|amazed|astounded|flabbergasted|gobsmacked|dumbfounded|nonplussed)\b", re.I)
# Which reaction a feeling said outright turns each interaction's own into.
_TURNS = {("look", "Scared"), ("avoid", "Surprised")}


def _said(text: str) -> str | None:
    fright, surprise = _FRIGHT.search(text), _SURPRISE.search(text)
    if fright and surprise:
        return None  # both said: the verb's own stays
    return "Scared" if fright else "Surprised" if surprise else None


def feelings_said_outright(prompt: str, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """The groups whose feeling about the robot is said in a phrase, with the reaction it says: from
    their own words, or the whole prompt's when they are the one group that reacts to the robot."""
    reacting = [g for g in groups if g.robot_interaction is not None]
    out = []
    for g in groups:
        feeling = _said(prompt if reacting == [g] else g.text)
        if g.robot_interaction is not None and (g.robot_interaction, feeling) in _TURNS:
            g = replace(g, robot_reaction=feeling)
        out.append(g)
    return tuple(out)
