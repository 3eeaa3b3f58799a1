"""A feeling of surprise fronted before its subject (round 47): "Startled, the temp at the photocopier
leaps back when the robot glides by", "Shocked, a porter jumps aside as it passes". Leaping or
shrinking back reads Scared (avoiding the robot), and `feeling_phrases.py` leaves "startled" and
"shocked" to the verb, since a start may be fright or surprise. Fronted on its own before the subject
and a comma, the word says how the person takes it: surprise, so the avoiding is Surprised. A
startled person ("a startled pensioner jumps back") and a fronted cause ("Startled by the robot, ...")
are left to the passes that read them; a fright said too ("in terror") keeps Scared."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading

_FRONTED = re.compile(r"(?:^|[.!?;]\s+)(?:(?:quite|a\s+(?:bit|little)|rather|completely|utterly)\s+)?"
                      r"(?:startled|surprised|shocked|stunned|taken\s+aback|caught\s+off[\s-]+guard|astonished|"
                      r"(?:taken|caught)\s+(?:completely\s+|quite\s+)?(?:by\s+surprise|unawares)|"
                      r"amazed|astounded|flabbergasted|gobsmacked|dumbfounded|nonplussed)\s*,\s*", re.I)
_FRIGHT = re.compile(r"\b(?:fright|terror|fear|panic|horror|dread|terrified|petrified|frightened|scared|panicked)\b",
                     re.I)


def sentence_after(prompt: str, start: int) -> str:
    """The rest of the sentence from `start` (to its stop, semicolon or the end)."""
    end = re.search(r"[.!?;](?:\s|$)", prompt[start:])
    return prompt[start:start + end.start()] if end else prompt[start:]


def surprised_when_fronted(prompt: str, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """The groups avoiding the robot after a fronted word of surprise, Surprised (module doc)."""
    out = list(groups)
    for m in _FRONTED.finditer(prompt):
        sentence = sentence_after(prompt, m.end())
        if _FRIGHT.search(sentence):
            continue
        reacting = [k for k, g in enumerate(out) if g.robot_interaction is not None]
        said = [k for k in reacting if out[k].text and out[k].text.lower() in sentence.lower()]
        chosen = said[:1] or (reacting if len(reacting) == 1 else [])
        for k in chosen:
            if out[k].robot_interaction == "avoid":
                out[k] = replace(out[k], robot_reaction="Surprised")
    return tuple(out)
