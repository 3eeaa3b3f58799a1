"""A load moved by hand along a route (round 27): "six stewardesses pull their wheelie cases from the
check-in hall to gate A2", "two roadies drag the flight cases out of the van into the hall", "a porter
tows the luggage cart across to the taxi rank". A verb of pushing, pulling or hauling whose object is
a thing (no person: someone moved by another is read elsewhere) followed, before the clause ends, by a
"to", "into" or "towards" of where, is the person walking that way with it; "pulls the lever", "pull
weeds out of the beds" with nowhere to go said stay what they were.
"""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Verbs of moving a load by hand.
LOAD_VERBS = frozenset("push pull drag tow trundle wheel cart heave tug haul lug hump schlep shove trolley".split())
# Words that open where the load goes.
_TO = frozenset({"to", "into", "towards", "toward", "onto"})
_OBJECT_PRONOUNS = frozenset({"him", "them", "us", "me", "you", "everyone", "everybody"})
_REACH = 12  # words from the verb to where the load goes


def _stem(s: Sentence, i: int) -> str:
    v = s.verb(i)
    if v in LOAD_VERBS:
        return v
    w = s.low[i]
    for cut, add in ((1, ""), (2, ""), (3, ""), (3, "e"), (2, "e"), (1, "e")):
        stem = w[:-cut] + add if len(w) > cut + 2 else ""
        if w.endswith(("s", "ing", "ed", "d")) and stem in LOAD_VERBS:
            return stem
    return verb_lemma(w)


def hauls_a_load(s: Sentence, i: int) -> bool:
    """Whether the verb at i moves a thing by hand along a route said after it ("pull their wheelie
    cases from the check-in hall to gate A2")."""
    if _stem(s, i) not in LOAD_VERBS or s.after_determiner(i) or i + 1 >= s.n:
        return False
    if s.low[i + 1] in _OBJECT_PRONOUNS or s.low[i + 1] in lx.ROBOT_WORDS:
        return False
    seen_thing = False
    for x in range(i + 1, min(i + 1 + _REACH, s.n)):
        w = s.low[x]
        if s.is_punct(x) and w not in ("-", "'", "’") or w in ("and", "but", "while", "as", "then") or s.low[x] in lx.ROBOT_WORDS:
            return False
        if s.lemma(x) in lx.PERSON_NOUNS or w in lx.PERSON_NOUNS:
            return False  # "pulls her son to the exit": a person led, read elsewhere
        if w in _TO and seen_thing and x + 1 < s.n and not s.verb_follows(x + 1):
            return True  # where the load goes: "pull weeds out of the beds" says none, a clearing out
        seen_thing = seen_thing or s.w[x].pos in ("NOUN", "PROPN")
    return False
