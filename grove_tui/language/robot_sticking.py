"""Reactions said by keeping close to the robot or keeping it off (round 28).

Sticking to the robot is following it: "sticks to the robot like glue", "stays glued to its side",
"sticks close to the robot all the way to the cafe", "keeps close behind it". Keeping the robot off a
place or away is blocking it: "link arms across the gate to keep the robot off the ice", "stand in the
doorway to keep it out of the hall", "form a chain to keep the robot away"."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Verbs that say sticking by themselves ("sticks to the robot", "is glued to it").
_STICKING = frozenset("stick glue cling".split())
# Their forms, which the parser may call nouns ("a girl in a onesie sticks to ...").
_STICKING_FORMS = frozenset("stick sticks sticking stuck glued clings clinging clung".split())
# Verbs of staying that stick with a word of closeness ("stays close to", "keeps right behind").
_STAYING = frozenset("stay keep remain hang".split())
_CLOSE = frozenset("close closely glued right tight tightly".split())
_TO = frozenset("to with by beside behind alongside on".split())
# Verbs of keeping away whose object is the robot ("keep the robot off the ice", "keep it out").
_KEEPING = frozenset("keep hold".split())
_OFF = frozenset("off out away back".split())


def _robot_at(s: Sentence, k: int) -> bool:
    return k < s.n and (s.low[k] in lx.ROBOT_WORDS or s.low[k] in ("it", "its") and
                        any(s.low[x] in lx.ROBOT_WORDS for x in range(k)))


def _robot_within(s: Sentence, k: int, steps: int) -> int | None:
    """The index of the robot ("the robot", "its", "the robot's") within `steps` words from k."""
    for x in range(k, min(k + steps, s.n)):
        if _robot_at(s, x):
            return x
        if s.is_punct(x) or s.is_verb(x):
            return None
    return None


def sticking_reaction(s: Sentence, own: Sequence[int]) -> str | None:
    """"follow" for sticking to the robot, "block" for keeping it off or away; None otherwise."""
    ownset = set(own)
    for i in own:
        if s.after_determiner(i):
            continue
        v = {verb_lemma(s.low[i]), s.verb(i)}
        k = i + 1
        if v & _STICKING or s.low[i] in _STICKING_FORMS or (v & _STAYING and k < s.n and s.low[k] in _CLOSE):
            while k < s.n and s.low[k] in _CLOSE | {"very", "so", "as"}:
                k += 1
            if k < s.n and s.low[k] in _TO and _robot_within(s, k + 1, 3) is not None:
                return "follow"  # "sticks to the robot like glue", "stays close behind it"
        if v & _KEEPING and (r := _robot_within(s, k, 3)) is not None and r in ownset | {r}:
            after = r + 1 + (r + 1 < s.n and s.low[r + 1] in ("'s", "’s"))
            if after < s.n and s.low[after] in _OFF:
                return "block"  # "to keep the robot off the ice", "keep it out of the hall"
    return None
