"""Robot clauses fronted by a time phrase of more than one word (round 59): "The moment the robot
nudges the door open, ...", "As soon as the robot rolls in, ...", "The instant it appears, ...",
"No sooner does the robot arrive than ...". Such an opener times the clause after it as "When the
robot ..." does (robot_idioms.timed_by_robot), and a fright in that clause is a reaction to the robot:
screaming or shrieking (not with delight), diving or crawling under or into something, bolting
(robot_idioms.timed_reaction)."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Nouns of a time phrase opened by "the" ("the moment the robot ...") and the words of "as soon as".
_THE_TIME_NOUNS = frozenset("moment minute second instant".split())
# Cries of fright: a reaction to the robot when its clause times them, unless said of joy.
_FRIGHT_CRIES = frozenset("scream shriek yelp squeal squeak wail howl whimper".split())
# Words after a cry that make it one of joy or fun ("screams with delight", "squeals happily").
_JOYFUL = frozenset("delight delighted excitement excited joy joyfully glee gleefully happily laughter "
                    "laugh laughing fun wonder amazement".split())
# Getting into or under something to hide ("dives into the wardrobe", "burrows under the covers").
_BURROWING = frozenset("dive burrow crawl scramble disappear vanish".split())
_INTO = frozenset("into under underneath beneath inside".split())


def opener_end(s: Sentence, k: int) -> int | None:
    """Where the robot's clause starts when a time phrase of several words starts at k, at the start
    of a sentence or after a stop: after "the moment", "as soon as", "no sooner"; else None."""
    if not (k == 0 or s.is_punct(k - 1)):
        return None
    if k + 1 < s.n and s.low[k] == "the" and s.low[k + 1] in _THE_TIME_NOUNS:
        return k + 2
    if k + 2 < s.n and (s.low[k], s.low[k + 1], s.low[k + 2]) == ("as", "soon", "as"):
        return k + 3
    if k + 1 < s.n and (s.low[k], s.low[k + 1]) == ("no", "sooner"):
        return k + 2
    return None


def fronted_robot_timer(s: Sentence, first: int) -> bool:
    """Whether a sentence's opener of several words, before the clause starting at `first`, leads
    into a robot clause ("The moment the robot ...", "As soon as it ..." once the robot was named)."""
    sentence = s.w[first].sentence
    for k in range(first):
        if s.w[k].sentence != sentence:
            continue
        start = opener_end(s, k)
        if start is None:
            continue
        if any(s.low[r] in lx.ROBOT_WORDS or (s.low[r] == "it" and _robot_named_before(s, k))
               for r in range(start, min(start + 3, first))):
            return True
    return False


def _robot_named_before(s: Sentence, k: int) -> bool:
    return any(s.low[j] in lx.ROBOT_WORDS for j in range(k))


def fright_reaction(s: Sentence, i: int) -> bool:
    """Whether the word at i is a fright: a cry not of joy ("screams", "shrieks", not "squeals with
    delight") or getting into or under something ("dives under the duvet", "crawls into a cupboard")."""
    if s.after_determiner(i) or s.w[i].pos not in ("VERB", "NOUN", "ADJ", "PROPN"):
        return False
    v = s.verb(i) if s.w[i].pos == "VERB" else verb_lemma(s.low[i])
    if v in _FRIGHT_CRIES or verb_lemma(s.low[i]) in _FRIGHT_CRIES:
        return not any(s.low[k] in _JOYFUL for k in range(i + 1, min(i + 4, s.n)))
    if v in _BURROWING or verb_lemma(s.low[i]) in _BURROWING:
        k = i + 1
        while k < s.n and (s.low[k] in ("back", "straight", "right") or s.low[k].endswith("ly")):
            k += 1
        return k < s.n and s.low[k] in _INTO
    return False
