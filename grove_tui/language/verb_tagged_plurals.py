"""A counted plural person noun the parser took for a verb ("two bell hops idle at ...", "three stage
hands lounge by ...", "a pair of deck hands loiter ..."): after a count and a kind word, a word in
"-s" tagged as a verb, then a people's verb in its plain form. Two verbs in a row cannot both be the
clause's, so the first is the plural noun the count counts and the second is what they do. Without
this the count counted nothing and the group was lost or read as an unnamed crowd."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_GROUP_OF = frozenset("pair trio couple quartet handful dozen score few".split())


def verb_tagged_plural(s: Sentence, i: int) -> bool:
    """Whether word i is "<count> <kind noun> <i: '-s' word tagged VBZ> <people's verb, plain>"."""
    word = s.w[i]
    low = s.low[i]
    if word.tag != "VBZ" or not low.isalpha() or not low.endswith("s") or len(low) < 4 or i < 2 or i + 1 >= s.n:
        return False
    nxt = s.low[i + 1]
    lemma = verb_lemma(nxt)
    if nxt != lemma or not (lemma in lx.INTENT_VERBS or lemma in lx.HUMAN_SUBJECT_VERBS or lemma in lx.PEOPLE_GOING_VERBS):
        return False  # "idle", "wait", "lounge": the plural's verb, in its plain form
    kind = i - 1
    if s.w[kind].pos not in ("NOUN", "PROPN", "ADJ") or s.index.knows(s.lemma(kind)) and s.w[kind].pos != "NOUN":
        return False
    base = low[:-1]
    if base in lx.NON_PEOPLE or base in lx.NON_PLACES or base in lx.HAZARD_NOUNS or base in lx.ROBOT_WORDS or \
            s.index.knows(base):
        return False
    before = kind - 1
    if s.w[before].pos == "NUM" and s.low[before] not in ("one", "1"):
        return True
    return before >= 1 and s.low[before] == "of" and s.lemma(before - 1) in _GROUP_OF
