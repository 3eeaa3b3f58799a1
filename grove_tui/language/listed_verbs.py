"""The verb of a list item's plural subject that the small parser tags a noun (round 37): "...,
two mechanics tinker with the pinsetters, and a couple bowl on lane 7", "a bellboy trundles a cart
to room 109, a couple of honeymooners paddle in the indoor pool, and ...". Read as nouns ("couple
bowl", "paddle"), the item's people are lost from the list. A singular noun heading a clause of its
own (the parser's clausal complement, conjunct or the like) whose subject is people in the plural
("honeymooners", "a couple of ...", "a couple"), followed by a preposition or an adverb, and which is a
verb of the language (the parser reads it a verb after "they"), is their verb."""

from __future__ import annotations

from dataclasses import replace
from functools import lru_cache

from grove_tui.language.parser import Word, parse

_CLAUSE_DEPS = frozenset({"ccomp", "conj", "parataxis", "advcl", "ROOT"})
_AFTER = frozenset({"ADP", "ADV", "PART"})
# a word for a few people, said as a singular noun ("a couple bowl", "a pair of cleaners mop")
_FEW = frozenset("couple pair trio foursome quartet handful few group bunch gang family party".split())


@lru_cache(maxsize=512)
def _a_verb(low: str) -> bool:
    """Whether the parser reads the word a verb after "they" ("they paddle in it")."""
    words = parse(f"They {low} in it.")
    return len(words) > 1 and words[1].lower == low and words[1].pos == "VERB"


def _plural_phrase(words: list[Word], j: int) -> bool:
    """Whether the phrase headed by word j is people in the plural."""
    w = words[j]
    if w.tag in ("NNS", "NNPS") and w.pos in ("NOUN", "PROPN"):
        return True
    if w.lower not in _FEW:
        return False
    return any(x.dep == "det" and x.head == j and x.lower in ("a", "the") for x in words[max(0, j - 3):j])


def as_listed_verbs(words: list[Word]) -> list[Word]:
    """The parse with a plural's verb, tagged a noun heading its own clause, tagged a verb (module doc)."""
    out = list(words)
    for k in range(1, len(words) - 1):
        w, nxt = words[k], words[k + 1]
        if w.pos != "NOUN" or w.tag != "NN" or w.dep not in _CLAUSE_DEPS or not w.lower.isalpha() or \
                nxt.pos not in _AFTER or nxt.sentence != w.sentence:
            continue
        subject = [j for j in range(k) if words[j].head == k and words[j].dep == "nsubj"
                   and words[j].sentence == w.sentence]
        prev = words[k - 1]
        few = k >= 2 and prev.head == k and prev.lower in _FEW and \
            words[k - 2].lower == "a" and words[k - 2].head in (k - 1, k)  # "couple" a modifier of the verb
        if not few and not (len(subject) == 1 and _plural_phrase(words, subject[0])):
            continue
        if w.dep == "ROOT" and not few:
            continue  # a plural right before the root noun is the plural-verbs reader's
        if not _a_verb(w.lower):
            continue
        out[k] = replace(w, pos="VERB", tag="VBP", lemma=w.lower)
        if few:  # "a couple bowl": "a couple" the subject
            out[k - 1] = replace(prev, dep="nsubj", head=k)
            out[k - 2] = replace(words[k - 2], dep="det", head=k - 1)
    return out
