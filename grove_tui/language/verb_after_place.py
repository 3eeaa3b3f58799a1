"""A verb in "-s" after a place phrase, tagged a noun (round 50): "a lad on the knife-skills course sidles
away from the robot". A word in "-s" that the world does not know, whose base is another word, right
before a particle of going ("away", "off", "past", "aside", "back", "towards") is the subject's verb,
not the last word of the place's name (place_phrases.py `_words`)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from grove_tui.language.heading_verbs import heading_verb_after
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma

_GOING_PARTICLES = frozenset("away off past aside back towards toward".split())


def verb_before_particle(s: Sentence, j: int) -> bool:
    """Whether the word at j is a verb in "-s" before a particle of going (module doc)."""
    w = s.low[j]
    return w.endswith("s") and not w.endswith("ss") and lemma(w) != w and j + 1 < s.n and \
        s.low[j + 1] in _GOING_PARTICLES and not s.index.knows(lemma(w)) and not s.index.knows(w)


def verb_after_place(s: Sentence, phrase: Sequence[str], j: int, whole_name: Callable[[Sequence[str]], bool]) -> bool:
    """Whether the word at j after a place phrase is the subject's verb: one in "-s" before a particle of
    going (module doc), or a base-form verb of heading off (heading_verbs.py)."""
    return verb_before_particle(s, j) or heading_verb_after(s, phrase, j, whole_name)
