"""Words shaped like a person noun the lexicon lacks (round 32): "two posties carry sacks", "a roadie
lugs a case", "the tapster wanders off", "three groundsmen walk". A word ending as English makes
nouns for people ("-ie", "-ies", "-ier", "-man", "-men", "-woman", "-ster"), opened by a count or a
determiner and followed by its verb, is the subject of the sentence, a person: no misspelt place word
("posties" is not "posts")."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace
from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.object_verbs import english_verb
from grove_tui.language.tokens import verb_lemma

if TYPE_CHECKING:
    from grove_tui.language.parser import Word

_ENDINGS = ("ie", "ies", "ier", "iers", "man", "men", "woman", "women", "ster", "sters")
_OPENERS = frozenset("a an the both some several few two three four five six seven eight nine ten eleven twelve "
                     "our their his her my your this that these those".split())


def person_shaped(words: Sequence[Word], k: int) -> bool:
    """Whether word k is a person noun by its shape and its place: opened by a count or a determiner
    (an adjective may come between) and followed by a verb."""
    low = words[k].lower
    if len(low) < 5 or not low.isalpha() or not low.endswith(_ENDINGS):
        return False
    if k + 1 >= len(words) or not (words[k + 1].tag.startswith("VB") or words[k + 1].tag == "MD"):
        return False
    j = k - 1
    if j >= 0 and words[j].pos == "ADJ":
        j -= 1  # "two burly posties"
    return j >= 0 and (words[j].lower in _OPENERS or words[j].lower in lx.NUMBER_WORDS or words[j].pos == "NUM")


# Endings of a person noun the parser takes for an adjective before its verb ("the sommelier darts",
# "the croupier bolts": tagged "JJ", "JJR").
_TAKEN_FOR_ADJECTIVES = ("ier", "ie", "man", "woman", "ster")
_ARTICLES = frozenset({"the", "a", "an"})
_AFTER_VERB = frozenset({"ADP", "ADV", "PART"})


def with_shaped_subjects(words: list[Word]) -> list[Word]:
    """The parse with a person noun taken for an adjective, opening its sentence after "the" or "a" and
    before its "-s" verb and a preposition ("The croupier bolts from the bar"), made the verb's subject."""
    out = list(words)
    for k in range(1, len(out) - 2):
        w, v, nxt, det = out[k], out[k + 1], out[k + 2], out[k - 1]
        if not (w.lower.isalpha() and len(w.lower) >= 6 and w.lower.endswith(_TAKEN_FOR_ADJECTIVES)
                and w.tag in ("JJ", "JJR") and w.head == k + 1 and det.lower in _ARTICLES):
            continue
        if k >= 2 and out[k - 2].sentence == w.sentence and out[k - 2].pos != "PUNCT":
            continue  # the phrase opens its sentence or follows a comma
        if v.dep != "ROOT" or not v.lower.endswith("s") or v.tag not in ("VBZ", "NNS") or nxt.pos not in _AFTER_VERB:
            continue
        base = verb_lemma(v.lower)
        if base == v.lower:
            base = v.lemma if v.lemma != v.lower else v.lower[:-1]
        out[k] = replace(w, pos="NOUN", tag="NN", dep="nsubj", head=k + 1)
        out[k + 1] = replace(v, pos="VERB", tag="VBZ", lemma=base)
        out[k - 1] = replace(det, head=k)
    return out


# Tags the small parser gives a word for people it misreads before its verb ("A steward hovers": an adverb).
_MISTAGGED = frozenset({"RB", "JJ", "JJR", "VBN", "NN"})


def with_listed_subjects(words: list[Word]) -> list[Word]:
    """The parse with a word the lexicon lists for people, tagged an adverb, an adjective or a noun's modifier after "a", "an"
    or "the" at the head of a sentence or a list's item and before its "-s" verb and a preposition ("A
    steward hovers near the info point, a pair of dads ..."), made the verb's subject (round 44). The verb,
    taken for a plural noun the sentence's subject, becomes the sentence's root, and the old root its
    second clause."""
    out = list(words)
    for k in range(1, len(out) - 2):
        w, v, nxt, det = out[k], out[k + 1], out[k + 2], out[k - 1]
        if w.tag not in _MISTAGGED or w.lower not in lx.PERSON_NOUNS or det.lower not in _ARTICLES or \
                w.head != k + 1 or nxt.pos not in _AFTER_VERB or nxt.sentence != w.sentence:
            continue
        if w.tag == "NN" and (w.dep != "compound" or v.tag != "NNS"):
            continue  # "a temp wrestles with ...": the person taken for a modifier of a plural "wrestles"
        if k >= 2 and out[k - 2].sentence == w.sentence and out[k - 2].lower not in (",", ";", "and"):
            continue  # the phrase opens its sentence or a list's item
        if not v.lower.endswith("s") or v.tag not in ("VBZ", "NNS"):
            continue
        base = verb_lemma(v.lower) if verb_lemma(v.lower) != v.lower else v.lemma if v.lemma != v.lower else v.lower[:-1]
        if v.tag == "NNS" and base == verb_lemma(v.lower) == v.lower or not english_verb(base):
            continue  # "a steward hovers": a verb of the language, not "a senior nurses"
        root = next((j for j, x in enumerate(out) if x.sentence == w.sentence and x.dep == "ROOT"), k + 1)
        out[k] = replace(w, pos="NOUN", tag="NN", dep="nsubj", head=k + 1)
        out[k + 1] = replace(v, pos="VERB", tag="VBZ", lemma=base, dep="ROOT" if root != k + 1 else v.dep,
                             head=k + 1 if root != k + 1 else v.head)
        out[k - 1] = replace(det, head=k)
        if root != k + 1:
            out[root] = replace(out[root], dep="conj", head=k + 1)
    return out
