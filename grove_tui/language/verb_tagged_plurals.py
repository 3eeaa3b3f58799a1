"""A counted plural person noun the parser took for a verb ("two bell hops idle at ...", "three stage
hands lounge by ...", "a pair of deck hands loiter ..."): after a count and a kind word, a word in
"-s" tagged as a verb, then a people's verb in its plain form. Two verbs in a row cannot both be the
clause's, so the first is the plural noun the count counts and the second is what they do. Without
this the count counted nothing and the group was lost or read as an unnamed crowd.

So too a plural tagged as a noun
(`counted_compound_person`, round 57): A counted two-word plural person whose last word the world or the lists also know as a thing
("a pair of stage hands loiter by ...", where a theatre has hand dryers; "two pot washers idle by ...";
"three deck hands wait ..."), followed by a people's verb in its plain form, whatever the parser made of
it ("loiter" as a noun, "idle" as an adjective). The plain verb agrees with the counted plural, so the
plural is the people the count counts and the verb is what they do; without this the word was a thing,
the count counted nothing and the group was read as an unnamed crowd (round 57)."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_GROUP_OF = frozenset("pair trio couple quartet handful dozen score few".split())


def _counted_before(s: Sentence, kind: int) -> bool:
    """Whether a count (more than one) or "a pair / trio / handful of" stands just before the kind word."""
    before = kind - 1
    if s.w[before].pos == "NUM" and s.low[before] not in ("one", "1"):
        return True
    return before >= 1 and s.low[before] == "of" and s.lemma(before - 1) in _GROUP_OF


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
    return _counted_before(s, kind)


def _people_verb(low: str) -> bool:
    lemma = verb_lemma(low)
    return low == lemma and (lemma in lx.INTENT_VERBS or lemma in lx.HUMAN_SUBJECT_VERBS or
                             lemma in lx.PEOPLE_GOING_VERBS or lemma in lx.ROBOT_WAIT_VERBS)


def counted_compound_person(s: Sentence, i: int) -> bool:
    """Whether word i is "<count> <kind noun> <i: plural noun> <people's verb, plain form>"."""
    low = s.low[i]
    if s.w[i].tag not in ("NNS", "NNPS") or not low.isalpha() or len(low) < 4 or i < 2 or i + 1 >= s.n:
        return False
    if not _people_verb(s.low[i + 1]):
        return False
    lem = s.lemma(i)
    if lem in lx.NON_PEOPLE or lem in lx.NON_PLACES or lem in lx.HAZARD_NOUNS or lem in lx.ROBOT_WORDS or \
            lem in lx.DURATION_UNITS or lem in lx.BUILDING_WORDS:
        return False
    kind = i - 1
    if s.w[kind].pos not in ("NOUN", "ADJ") or not s.low[kind].isalpha() or s.low[kind] in lx.ROBOT_WORDS or \
            s.w[kind].tag in ("NNS", "NNPS"):
        return False
    return _counted_before(s, kind)
