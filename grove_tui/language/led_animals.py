"""Animals led, walked or carried along (round 63): "a kennel hand leads a nervous collie to the dog
field", "a farmer leads two heifers into the barn". The parse makes the led one a group that follows its
leader; an animal is nobody a crowd simulation places, so that group goes. Whether the led one is an animal
is read by kind, not by a list of breeds: a noun no list of people names whose meaning (the embedding
model of meaning.py) is much nearer "an animal" than "a person" ("collie", "spaniel", "pony", "ferret").
Without the model only the lexicon's list of animals decides, for a word with no hyphen (a
"first-timer" ends in a timer).
"""

from __future__ import annotations

from collections.abc import Sequence
from functools import lru_cache

import numpy as np

from grove_tui.language import lexicon as lx
from grove_tui.language.meaning import MiniLM
from grove_tui.language.model import GroupReading
from grove_tui.language.tokens import lemma

# How much nearer "an animal" than "a person" a noun's meaning must be (a collie +0.35, a pony +0.18, a
# jockey -0.05, a baby -0.08, a patient -0.33).
_ANIMAL_MARGIN = 0.1


def led_animals(groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """The groups without the followers that are animals led along, when no later group refers to one
    by its place in the list and a person remains."""
    out = list(groups)
    for i in range(len(out) - 1, -1, -1):
        g = out[i]
        if g.intent != "follow" or len(out) < 2 or not is_animal(g.label):
            continue
        if any(h.relation for h in out[i:]):
            continue
        del out[i]
    return tuple(out)


@lru_cache(maxsize=512)
def is_animal(label: str) -> bool:
    """Whether a group's label names an animal rather than a person, by kind."""
    words = label.lower().split()
    if not words:
        return False
    head = lemma(words[-1])
    if head in lx.PERSON_NOUNS or words[-1] in lx.PERSON_NOUNS:
        return False
    model = MiniLM.shared()
    if model is None:
        return "-" not in words[-1] and head in lx.NON_PEOPLE  # not "first-timer", whose end is a timer
    vectors = model.encode([f"a {words[-1]}", "an animal", "a person"])
    vectors = vectors / np.linalg.norm(vectors, axis=1, keepdims=True)
    to_animal, to_person = float(vectors[0] @ vectors[1]), float(vectors[0] @ vectors[2])
    return to_animal - to_person >= _ANIMAL_MARGIN
