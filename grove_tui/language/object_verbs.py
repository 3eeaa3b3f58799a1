"""Verbs the small parser takes for plural nouns between one person and the plural thing they work on
(round 40): "my sister-in-law irons shirts in the bedroom", "a maid folds towels in the laundry", "the
caretaker stacks chairs in the hall". Read as nouns, "irons shirts" is a thing in apposition and the
person's clause is lost; read by its place, an "-s" word that English has as a verb, right after one
person and right before a bare plural noun and then a preposition, a comma or the end, is that
person's verb and the plural noun its object."""

from __future__ import annotations

from dataclasses import replace
from functools import lru_cache

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import Word, load

# What may follow the object: a place, a time, the next clause or the end.
_AFTER_OBJECT = frozenset({"ADP", "PUNCT", "SCONJ", "CCONJ", "ADV"})
# Person words the lexicon keeps in parts ("sister-in-law": "law" ends it).
_IN_LAW = "law"
# Endings of words for one who works ("chambermaid", "handyman", "stacker", "florist").
_WORKERS = ("maid", "man", "woman", "person", "er", "or", "ist")


@lru_cache(maxsize=1)
def _english_verbs() -> frozenset[str]:
    """The base forms the parser's lemmatizer lists as verbs (WordNet's verb index)."""
    lookups = getattr(load().get_pipe("lemmatizer"), "lookups", None)
    if lookups is None or "lemma_index" not in lookups.tables:
        return frozenset()
    return frozenset(lookups.get_table("lemma_index").get("verb", []))


def english_verb(base: str) -> bool:
    """Whether a base form is a verb of the language (WordNet's verb index, as the parser ships it)."""
    return base in _english_verbs()


def _one_person(words: list[Word], k: int) -> int | None:
    """The head of the one person whose phrase ends right before k, else None."""
    prev = words[k - 1]
    worker = prev.lower.endswith(_WORKERS) and prev.lemma not in lx.NON_PEOPLE and k >= 2 and \
        words[k - 2].lower in ("a", "an", "the", "my", "our", "his", "her", "their")
    person = (prev.lower in lx.PERSON_NOUNS or worker) and prev.tag in ("NN", "NNP", "VBN", "JJ", "JJR") or (
        prev.lower == _IN_LAW and k >= 5 and words[k - 2].lower == "-" and words[k - 3].lower == "in")
    if not person:
        return None
    head = k - 1
    while words[head].head < k and words[head].head != head and words[words[head].head].sentence == prev.sentence:
        head = words[head].head
    if any(x.pos in ("VERB", "AUX") for x in words[:head] if x.sentence == prev.sentence):
        return None  # a verb before it: "they watch the porter irons ..." is no such phrase
    if any(x.tag in ("NNS", "NNPS") or x.pos == "NUM" for x in words[:k] if x.sentence == prev.sentence):
        return None  # more than one said before
    return head


def _verb_before_object(words: list[Word], k: int) -> int | None:
    w = words[k]
    low = w.lower
    if k < 2 or k + 2 >= len(words) or w.pos != "NOUN" or w.tag != "NNS" or not low.isalpha() or \
            not low.endswith("s") or low.endswith(("ss", "us", "is")):
        return None
    obj = words[k + 1]
    # "irons pillowcases": no verb; "a cleaner empties bins": the person's word then the thing
    taken_for_verb = obj.tag == "VBZ" and (obj.lemma not in _english_verbs() or (
        w.dep == "nsubj" and w.head == k + 1 and words[k - 1].lower in lx.PERSON_NOUNS))
    if not (obj.pos == "NOUN" and obj.tag == "NNS" or taken_for_verb) or obj.sentence != w.sentence or words[k + 2].pos not in _AFTER_OBJECT:
        return None
    base = w.lemma if w.lemma != low else low[:-1]
    if base not in _english_verbs() or base in lx.INTENT_VERBS:
        return None  # "the intern files reports": a verb of going too, which the reader reads by its own rules
    return _one_person(words, k)


def as_object_verbs(words: list[Word]) -> list[Word]:
    """The parse with such verbs tagged verbs, their person the subject and the plural noun the object."""
    out = list(words)
    for k in range(len(words)):
        head = _verb_before_object(out, k)
        if head is None:
            continue
        w = out[k]
        base = w.lemma if w.lemma != w.lower else w.lower[:-1]
        old = out[head]
        out[k] = replace(w, pos="VERB", tag="VBZ", lemma=base, dep="ROOT", head=k)
        out[head] = replace(old, pos="NOUN" if old.pos == "VERB" else old.pos, tag="NN" if old.pos == "VERB" else old.tag,
                            dep="nsubj", head=k)
        out[k + 1] = replace(out[k + 1], pos="NOUN", tag="NNS", dep="dobj", head=k)
        for j in range(len(out)):
            if j in (k, head) or out[j].sentence != w.sentence:
                continue
            if out[j].head == k and j < k:
                out[j] = replace(out[j], head=head)  # "my mum": words of the person, not of the verb
            elif j > k + 1 and out[j].head in (head, k + 1) and out[j].dep == "prep":
                out[j] = replace(out[j], head=k)  # "in the kitchen": where the verb is done
    return out
