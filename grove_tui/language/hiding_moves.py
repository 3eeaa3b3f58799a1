"""Hiding said by a quick move behind or under something (round 28): "dives behind the settee every
time the robot beeps", "darts under the table whenever it comes near", "scrambles behind the counter
as the robot rolls in". In a clause the robot's own clause times, a verb of a quick or low move whose
next words are "behind", "under" or "beneath" is hiding from the robot: avoiding it (Scared)."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Verbs of a quick or low move that, with a word of hiding after, are hiding.
_DARTING_VERBS = frozenset("dive leap jump dart scramble scurry scuttle crawl scoot duck nip slip run rush "
                           "bolt dash hurry creep shuffle squeeze wriggle tuck huddle".split())
# Words of where one hides.
_HIDING_WORDS = frozenset("behind under underneath beneath".split())


def hides_by_moving(s: Sentence, i: int) -> bool:
    """Whether the verb at i is a quick move to hide: a verb of darting with "behind"/"under" next,
    past "back", "straight" or "quickly" ("dives straight behind the sofa")."""
    if s.w[i].pos not in ("VERB", "NOUN", "PROPN", "ADJ") or s.after_determiner(i):
        return False
    if verb_lemma(s.low[i]) not in _DARTING_VERBS and s.verb(i) not in _DARTING_VERBS:
        return False
    k = i + 1
    while k < s.n and (s.low[k] in ("back", "straight", "right", "off") or s.low[k].endswith("ly")):
        k += 1
    return k < s.n and s.low[k] in _HIDING_WORDS
