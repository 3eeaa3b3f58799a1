"""One person's verb after a participle of where they are (round 33): "A nervous flyer sitting at the
A1 seats shrinks back whenever the robot rolls close", "a shy toddler standing by the pool flinches".
The small parser reads the "-s" verb as a plural noun after the place ("seats shrinks"), and the
participle keeps `subject_phrases` (a person, place phrases, then the verb) from reading it: the person
was lost and a vague crowd made up. A participle of sitting, standing or waiting right after a singular
noun phrase, then its place phrase, is read as that phrase's place, and the "-s" word after it as the
person's verb."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language.parser import Word
from grove_tui.language.subject_phrases import subject_before

# Participles of being somewhere, said of a person right after them ("a flyer sitting at ...").
POSTURES = frozenset("sitting standing waiting perched lounging sprawled slumped hovering lingering kneeling "
                     "crouching queuing queueing seated squatting leaning loitering resting huddled hunched "
                     "curled stationed posted sat stood".split())
_AFTER_POSTURE = frozenset("at by in on near beside behind outside inside next opposite under against round "
                           "around".split())


def subject_of(words: list[Word], k: int) -> int | None:
    """The one person whose verb is the "-s" word at k: after place phrases (`subject_before`), or
    after a participle of where they are and its place phrase (module doc)."""
    found = subject_before(words, k)
    if found is not None:
        return found
    w = words[k]
    for p in range(k - 2, 0, -1):
        x = words[p]
        if x.sentence != w.sentence or x.lower in (",", ";", ":", "and", "or", "while"):
            return None
        if x.lower in POSTURES and words[p + 1].lower in _AFTER_POSTURE and words[p - 1].pos in ("NOUN", "PROPN"):
            as_place = list(words)
            as_place[p] = replace(x, lower="at", text="at", pos="ADP", tag="IN")
            subject = subject_before(as_place, k)
            return subject if subject == p - 1 else None
    return None
