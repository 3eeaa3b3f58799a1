"""A person's verb the small parser takes for a plural noun before a gerund (round 58): "while the
junior captain practises chipping on ...", "the senior curator practises sketching in ...". Read as
nouns, "captain practises" is a crowd of practices, the person is lost and the clause's people are
read as an unnamed crowd. An "-s" word right after a singular noun, itself after a determiner and
describing words only (its clause opened by the sentence or a subordinator such as "while"), and
followed by a gerund, is the clause's verb: two nouns then a gerund leave the gerund no subject, and
an "-s" verb with a gerund object ("practises chipping", "keeps sweeping") is plain English."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import Word
from grove_tui.language.tokens import lemma

_OPENERS = frozenset({"while", "whilst", "as", "when", "meanwhile"})
_DETERMINERS = frozenset({"the", "a", "an", "our", "their", "his", "her", "my", "one"})


def _subject_before(words: list[Word], k: int) -> bool:
    """Whether words k-1 back to a determiner are one singular noun phrase opening its clause."""
    noun = words[k - 1]
    if noun.tag != "NN" or not noun.lower.isalpha() or lemma(noun.lower) not in lx.PERSON_NOUNS and \
            noun.pos != "NOUN":
        return False
    j = k - 2
    while j >= 0 and words[j].pos in ("ADJ", "NOUN") and words[j].tag in ("JJ", "NN") and \
            words[j].sentence == noun.sentence:
        j -= 1
    if j < 0 or words[j].lower not in _DETERMINERS:
        return False
    before = j - 1
    return before < 0 or words[before].sentence != noun.sentence or words[before].lower in _OPENERS or \
        words[before].lower == ","


def _taken_for_noun(words: list[Word], k: int) -> bool:
    w = words[k]
    low = w.lower
    if w.tag != "NNS" or not low.isalpha() or len(low) < 5 or not low.endswith("s") or \
            low.endswith(("ss", "us", "is")) or k < 2 or k + 1 >= len(words):
        return False
    nxt = words[k + 1]
    if nxt.tag != "VBG" or nxt.sentence != w.sentence:
        return False
    base = lemma(low)
    if base in lx.PERSON_NOUNS or base in lx.ROBOT_WORDS:
        return False
    return _subject_before(words, k)


def as_verbs_before_gerunds(words: list[Word]) -> list[Word]:
    """The parse with the "-s" verb taken for a noun before a gerund tagged a verb (module doc)."""
    out = list(words)
    for k in range(len(words)):
        if not _taken_for_noun(out, k):
            continue
        w, gerund = out[k], out[k + 1]
        base = w.lemma if w.lemma != w.lower else w.lower[:-1]
        for j in range(k):  # "While" marked the gerund: it marks the verb now
            if out[j].head in (k, k + 1) and out[j].sentence == w.sentence:
                out[j] = replace(out[j], head=k)
        out[k] = replace(w, pos="VERB", tag="VBZ", lemma=base, dep=gerund.dep, head=gerund.head)
        out[k - 1] = replace(out[k - 1], dep="nsubj", head=k)
        out[k + 1] = replace(gerund, dep="xcomp", head=k)
        for j in range(k + 2, len(words)):
            if out[j].head == k and out[j].sentence == w.sentence:
                out[j] = replace(out[j], head=k + 1)
    return out
