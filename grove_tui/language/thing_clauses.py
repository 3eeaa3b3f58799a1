"""Clauses whose subject is a thing, said after a word of time (round 14): "queuing for tickets before
the bus leaves", "wait in the lounge while the kettle boils", "sit in the garden till the rain stops".
The thing's verb says when, not what the people do, so it gives them no intent; their own verb does,
even when it is a participle ("five people queuing ...") the reader would otherwise take for who they are.
"""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence

# Words that open a clause of time or reason after the people's own clause.
SUBORDINATORS = frozenset("before after until till til while as when once whilst because since".split())


def a_things_verb(s: Sentence, i: int) -> bool:
    """Whether the verb at i has a thing for its subject, in a clause opened by a word of time or reason
    ("before the bus leaves"), so its people are not its subject."""
    subjects = [k for k in range(max(0, i - 6), i) if s.w[k].head == i and s.w[k].dep in ("nsubj", "nsubjpass")]
    if not subjects:
        return False
    k = subjects[0]
    if s.w[k].pos not in ("NOUN", "PROPN") or s.lemma(k) in lx.PERSON_NOUNS or s.low[k] in lx.PERSON_NOUNS or \
            s.lemma(k) in lx.ROBOT_WORDS or s.low[k] in lx.ROBOT_WORDS:
        return False
    opener = k - 1
    while opener > 0 and (s.w[opener].pos in ("DET", "ADJ", "NOUN", "PROPN", "NUM") or s.low[opener] in ("'s", "’s")):
        opener -= 1
    return s.low[opener] in SUBORDINATORS
