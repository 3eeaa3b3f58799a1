"""A threat made at the robot by a gesture (round 43): "shakes his fist at the robot", "jabs a finger
at it", "wags a finger at the robot", "brandishes an umbrella at it", "makes a rude gesture at the
robot", "sticks two fingers up at it", and going at it ("lunges at the robot", "swings at it"). Aimed "at" the robot these are hostile (HuNavSim's Threatening,
the reader's block), not a look as other things done "at" it are ("waves at the robot", "points a
finger at it")."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma, verb_lemma

# Held up or shaken in anger whatever the verb ("raises a fist", "waves his fists").
_ANGRY_THINGS = frozenset("fist fists".split())
# Verbs of thrusting or shaking a thing at someone: hostile with a finger or a thing held ("jabs a
# finger", "wags a finger", "waves a brolly"), not with a hand in greeting ("waves a flag").
_THRUSTING_VERBS = frozenset("jab wag shake wave brandish thrust poke stab wield".split())
_HELD_THINGS = frozenset("finger fingers umbrella brolly stick cane crutch bat broom mop pole bottle".split())
# Verbs hostile whatever is held ("brandishes a newspaper at it").
_ALWAYS_HOSTILE = frozenset("brandish wield".split())
# A gesture said to be hostile ("a rude gesture", "an obscene sign").
_GESTURES = frozenset("gesture gestures sign signs".split())
_HOSTILE_MARKS = frozenset("rude obscene threatening angry aggressive menacing crude vulgar".split())
# Verbs of going at someone to hurt or insult them, hostile with "at" alone ("lunges at the robot", "swings
# at it", "charges at the robot", "lashes out at it", "spits at it").
_ATTACKING_VERBS = frozenset("lunge swing charge lash spit swipe snarl growl kick hurl snap".split())
_WITHIN = 5  # words from the gesture to the "at" before the robot


def _at_before(s: Sentence, r: int) -> int | None:
    """The "at" just before the robot at r ("at the robot", "at it", "up at our robot"), else None."""
    k = r - 1
    while k >= 0 and s.low[k] in ("the", "this", "that", "our", "their", "its", "poor", "little", "new"):
        k -= 1
    return k if k >= 0 and s.low[k] == "at" else None


def _hostile_at(s: Sentence, own: set[int], at: int) -> bool:
    for k in range(max(0, at - _WITHIN), at):
        if k not in own or s.is_punct(k):
            continue
        word = s.low[k]
        if word in _ANGRY_THINGS:
            return True  # "shakes his fist at the robot"
        if word in _GESTURES and any(s.low[j] in _HOSTILE_MARKS for j in range(max(0, k - 3), k)):
            return True  # "makes a rude gesture at it"
        if word in ("fingers", "finger") and k + 1 < at and s.low[k + 1] == "up":
            return True  # "sticks two fingers up at the robot"
        verb = verb_lemma(word) if verb_lemma(word) != word else lemma(word)  # "jabs", which the lexicon lacks
        if verb in _ALWAYS_HOSTILE and not s.after_determiner(k):
            return True
        if verb in _ATTACKING_VERBS and not s.after_determiner(k) and all(
                s.low[j] in ("out", "wildly", "angrily", "suddenly", "straight") for j in range(k + 1, at)):
            return True  # "lunges at the robot", "lashes out at it"
        if verb in _THRUSTING_VERBS and not s.after_determiner(k) and any(
                lemma(s.low[j]) in _HELD_THINGS or s.low[j] in _HELD_THINGS for j in range(k + 1, at)):
            return True  # "jabs a finger at the robot", "wags his umbrella at it"
    return False


def gesture_threat(s: Sentence, own: Sequence[int], robot_at: Sequence[int]) -> bool:
    """Whether the clause makes a threatening gesture at the robot it names at one of `robot_at`."""
    ownset = set(own)
    for r in robot_at:
        at = _at_before(s, r)
        if at is not None and at in ownset and _hostile_at(s, ownset, at):
            return True
    return False
