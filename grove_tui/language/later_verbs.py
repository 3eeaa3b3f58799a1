"""The verb of one person in a later clause of a list, taken for a plural noun (round 26): "A cleaner
mops the food court, a courier wheels parcels from ... to ..., and a busker plays ...", "a guard walks
to the toy store and a busker sings in the atrium". The parser reads "courier wheels" and "busker sings"
as nouns and the person is lost. singular_verbs.py reads this for a sentence's first clause only; here a
clause opened after a comma or "and" by "a", "an", "one" or "the", then one singular noun, then an "-s"
word the lexicon knows as a verb (or the parse's head of a clause), is that person and their verb."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import Word
from grove_tui.language.tokens import verb_lemma

_OPENERS = frozenset({"a", "an", "one", "the"})
_BOUNDARIES = frozenset({",", "and", ";", "while", "whilst", "as"})
_AFTER = frozenset({"ADP", "ADV", "DET", "PRON", "NUM", "PART", "PUNCT", "SCONJ", "CCONJ"})
# Verbs whose object may follow straight after ("wheels parcels", "pushes trolleys").
_OBJECT_VERBS = lx.HOLDING_VERBS | lx.THING_OR_PLACE_VERBS | lx.LEADING_VERBS | frozenset("push pull drag".split())


def _later_verb(words: list[Word], k: int) -> bool:
    w = words[k]
    low = w.lower
    if k < 3 or w.pos != "NOUN" or w.tag != "NNS" or not low.isalpha() or len(low) < 4 or \
            low.endswith(("ss", "us", "is")):
        return False
    base = verb_lemma(low)
    if base == low and w.dep not in ("conj", "ROOT"):
        return False  # neither a verb the lexicon knows nor the head of a clause of its own
    noun, opener, boundary = words[k - 1], words[k - 2], words[k - 3]
    if noun.tag != "NN" or noun.pos != "NOUN" or opener.lower not in _OPENERS or boundary.lower not in _BOUNDARIES:
        return False
    if any(x.sentence != w.sentence for x in (noun, opener, boundary)):
        return False
    if not (noun.lower in lx.PERSON_NOUNS or noun.lower.endswith(lx.AGENT_SUFFIXES)):
        return False  # "and the coffee shops in the atrium": a place, no person
    nxt = words[k + 1] if k + 1 < len(words) and words[k + 1].sentence == w.sentence else None
    if base == low:  # a verb only by the parse: a place or a way must follow ("sings in the atrium")
        return nxt is not None and nxt.pos in ("ADP", "ADV")
    return nxt is None or nxt.pos in _AFTER or (base in _OBJECT_VERBS and nxt.pos in ("NOUN", "ADJ"))


def as_later_verbs(words: list[Word]) -> list[Word]:
    """The parse with a later clause's verb of one person, taken for a plural noun, tagged a verb."""
    out = list(words)
    for k in range(len(out)):
        if not _later_verb(out, k):
            continue
        w = out[k]
        root = next((j for j, x in enumerate(out) if x.sentence == w.sentence and x.dep == "ROOT"), k)
        base = verb_lemma(w.lower)
        base = base if base != w.lower else (w.lemma if w.lemma != w.lower else w.lower[:-1])
        out[k] = replace(w, pos="VERB", tag="VBZ", lemma=base, dep="conj" if root != k else "ROOT",
                         head=root if root != k else k)
        out[k - 1] = replace(out[k - 1], dep="nsubj", head=k)
        out[k - 2] = replace(out[k - 2], dep="det", head=k - 1)
        for j in range(k + 1, len(out)):
            if out[j].head == k - 1 and out[j].sentence == w.sentence:
                out[j] = replace(out[j], head=k)
    return out
