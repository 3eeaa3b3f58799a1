"""Where a timed robot clause hands back to the person who reacts to it (round 50): "A junior jumps in
surprise when the robot rolls past and hops out of its way". After the robot's verb, "and" and a verb
whose phrase goes "out of its way", "away from it", "at it" or "after it" names the robot as that verb's
object: the robot does not step out of its own way, so the verb is the reacting person's, and the robot's
clause ends at the "and" (robot.py `_end`), leaving the words to that person's clause."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_TIME_WORDS = frozenset("as when whenever once".split())
# A preposition before "it" that makes the robot the object of someone's reaction.
_AT_IT = frozenset("from at after".split())


def hands_back(s: Sentence, first: int, j: int) -> bool:
    """Whether the robot clause opened at `first` by a word of time ends at the "and" at j, the verb
    after it reacting to the robot (module doc)."""
    if s.low[j] != "and" or first < 1 or s.low[first - 1] not in _TIME_WORDS or j + 1 >= s.n:
        return False
    v = j + 1
    if not (s.w[v].pos == "VERB" or s.w[v].tag.startswith("VB") or verb_lemma(s.low[v]) != s.low[v]):
        return False
    k = v + 1
    while k < min(s.n, v + 7) and not s.is_punct(k) and s.low[k] not in lx.CLAUSE_STARTERS:
        if s.low[k] == "its" and s.low[k - 1] == "of" and k + 1 < s.n and s.low[k + 1] in ("way", "path"):
            return True  # "hops out of its way"
        if s.low[k] == "it" and s.low[k - 1] in _AT_IT:
            return True  # "backs away from it", "glares at it"
        k += 1
    return False
