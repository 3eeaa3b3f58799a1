"""Things that fail or break down, said as a clause's subject (round 44): "The power fails and the
grocery store is evacuated", "the water cuts out", "the heating packs up", "the router crashes". A noun
ending as agents' nouns do ("power", "water", "router") and in no list of people, the subject of a
verb of failing with nothing for it to do after it ("fails", not "fails to turn up"), is a thing that
broke: no person, and no group of one."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence

# What supplies and machines do when they break down; not "collapse", "trip" or "faint" (people do those).
FAILING_VERBS = frozenset("fail crash malfunction flicker leak burst overheat jam short-circuit".split())
# Phrasal ways of failing: the verb and its particle ("cuts out", "packs up", "goes off").
_FAILING_PHRASES = frozenset({("cut", "out"), ("pack", "up"), ("conk", "out"), ("give", "out"), ("go", "off"),
                              ("go", "out"), ("go", "down"), ("break", "down"), ("pack", "in")})


def failing_thing(s: Sentence, i: int) -> bool:
    """Whether the noun at i is the subject of a verb of failing and no person noun (module doc)."""
    w = s.w[i]
    lem = s.lemma(i)
    if w.pos not in ("NOUN", "PROPN") or w.dep != "nsubj" or w.head == i or lem in lx.PERSON_NOUNS or \
            s.low[i] in lx.PERSON_NOUNS:
        return False
    v = w.head
    verb = s.verb(v)
    nxt = s.low[v + 1] if v + 1 < s.n else ""
    if verb in FAILING_VERBS:
        return nxt != "to"  # "the plumber fails to turn up": a person who does not come
    return (verb, nxt) in _FAILING_PHRASES
