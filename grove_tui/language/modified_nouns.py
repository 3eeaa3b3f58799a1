"""A verb's word used as a noun after a determiner and its adjectives (round 51): "scurries off to the far
corner", "to a quiet corner", "the big stop". `Sentence.after_determiner` sees only "the corner"; a word
of the robot's verbs ("corner", "stop", "block") said this way names a thing, no act on the robot, so a
person fleeing "to the far corner" as the robot appears avoids it rather than cornering it."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence

# Determiners that open a noun phrase (as `Sentence.after_determiner`).
_DETERMINERS = frozenset("the a an their its his her our my this that".split())


def after_modified_determiner(s: Sentence, i: int) -> bool:
    """Whether word i follows a determiner with one or two adjectives between ("the far corner")."""
    if s.w[i].pos != "NOUN":
        return False  # "a patient stares": the parser's adjective is the person, the verb a verb
    k = i - 1
    while k >= 0 and k >= i - 2 and s.w[k].pos in ("ADJ", "ADV") and s.low[k] not in _DETERMINERS and \
            s.low[k] not in lx.PERSON_NOUNS:
        k -= 1
    return k < i - 1 and k >= 0 and s.low[k] in _DETERMINERS
