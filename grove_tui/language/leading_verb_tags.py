"""Verbs of taking someone along that the small parser tags as names or nouns (round 36): "A pair of
constables march a detained shoplifter from custody ..." ("march" a proper noun, the sentence's root),
"A porter wheels frail Mrs Patel from ..." ("wheels" a plural noun, "frail" the verb), "A porter and a
nurse wheel Mr Jones to ..." ("nurse wheel" one noun, the porter the sentence's root). Read so, the
person taken along, or the one taking them, is lost. Here such a word, between its subject and the
person it takes, is tagged the verb it is, and a describing word the parser made the verb after it
goes back to describing the person."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import Word
from grove_tui.language.tokens import lemma, verb_lemma

_LEADING = lx.LEADING_VERBS | frozenset({"march", "frogmarch", "bundle", "hustle", "trundle"})
_OPENERS = frozenset({"a", "an", "the", "his", "her", "their", "our", "my"})


def _lemma(w: Word) -> str | None:
    low = w.lower
    if not low.isalpha():
        return None
    base = verb_lemma(low)
    if base in _LEADING:
        return base
    if low.endswith("s") and low[:-1] in _LEADING:
        return low[:-1]
    return low if low in _LEADING else None


def _name_after(out: list[Word], v: int) -> int | None:
    """The name the parser hung on word v, after describing words and a title ("frail old Mr Dobbs")."""
    for j in range(v + 1, min(v + 5, len(out))):
        w = out[j]
        if w.pos == "PROPN" and w.text[:1].isupper() and w.head == v and w.dep in ("dobj", "nsubj", "appos"):
            return j
        if w.pos not in ("ADJ", "PROPN") or not w.text[:1].isalpha():
            return None
    return None


def as_leading_verbs(words: list[Word]) -> list[Word]:
    """The parse with a verb of taking someone along, tagged a name or noun, tagged a verb (module doc)."""
    out = list(words)
    for k, w in enumerate(out):
        if k == 0 or k + 2 >= len(out) or w.pos not in ("PROPN", "NOUN") or out[k + 1].sentence != w.sentence:
            continue
        base = _lemma(w)
        if base is None:
            continue
        third = w.lower.endswith("s") and w.lower != base
        verb_tag = "VBZ" if third else "VBP"
        subject = [j for j in range(k) if out[j].dep == "nsubj" and out[j].head == k and out[j].sentence == w.sentence]
        obj = [j for j in range(k + 1, len(out)) if out[j].dep == "dobj" and out[j].head == k]
        if w.dep == "ROOT" and subject and obj and out[k + 1].lower in _OPENERS:
            # "A pair of constables march a detained shoplifter": the parse is right but for the tag
            out[k] = replace(w, pos="VERB", tag=verb_tag, lemma=base)
            continue
        nxt, after = out[k + 1], out[k + 2]
        prev = out[k - 1]
        if third and w.dep == "nsubj" and nxt.dep == "ROOT" and w.head == k + 1 and nxt.pos in ("VERB", "ADJ") and \
                prev.pos == "NOUN" and prev.tag == "NN" and after.pos in ("ADJ", "PROPN"):
            # "A porter wheels frail Mrs Patel": "wheels" the verb, "porter" its subject, "frail" describes her
            name = _name_after(out, k + 1)
            if name is None:
                continue
            for j in range(len(out)):
                if out[j].head == k + 1 and j not in (k, k + 1):
                    out[j] = replace(out[j], head=k)
                elif out[j].head == k and j < k - 1:
                    out[j] = replace(out[j], head=k - 1)
            out[k - 1] = replace(prev, dep="nsubj", head=k)
            out[k] = replace(w, pos="VERB", tag=verb_tag, lemma=base, dep="ROOT", head=k)
            out[k + 1] = replace(nxt, pos="ADJ", tag="JJ", lemma=nxt.lower, dep="amod", head=name)
            out[name] = replace(out[name], dep="dobj", head=k)
        elif w.dep == "conj" and not third and _joined_taker(out, k):
            out = _as_joined_takers_verb(out, k, base)
    return out


def _joined_taker(out: list[Word], k: int) -> bool:
    """Whether word k, a noun the parser joined to a person at the sentence's root, follows a second person it
    took for its modifier and comes before the person taken ("A porter and a nurse wheel Mr Jones")."""
    first, prev = out[k].head, out[k - 1]
    if not (first < k - 2 and out[first].dep == "ROOT" and lemma(out[first].lower) in lx.PERSON_NOUNS
            and prev.dep == "compound" and prev.head == k and lemma(prev.lower) in lx.PERSON_NOUNS):
        return False
    if any(x.pos in ("VERB", "AUX") for x in out[:k] if x.sentence == out[k].sentence):
        return False  # a verb before it is the people's ("... while two visitors wait" after it is not)
    return "and" in (x.lower for x in out[first + 1:k - 1]) and out[k + 1].lower in _OPENERS | {"mr", "mrs", "ms", "miss"} \
        or out[k + 1].pos == "PROPN" and out[k + 1].text[:1].isupper()


def _as_joined_takers_verb(out: list[Word], k: int, base: str) -> list[Word]:
    """The parse of "A porter and a nurse wheel Mr Jones to ...": the verb the root of both people, the first
    person its subject and the second joined to it, the person taken its object."""
    out = list(out)
    first = out[k].head
    for j in range(len(out)):
        if j > k and out[j].head == first:
            out[j] = replace(out[j], head=k)  # "to the pharmacy": the verb's way, not the porter's
        elif j < k - 1 and out[j].head == k:
            out[j] = replace(out[j], head=k - 1)  # "a" of "a nurse"
    taken = next((j for j in range(k + 1, len(out)) if out[j].head == k and out[j].dep in ("appos", "dobj", "compound")), None)
    if taken is not None:
        out[taken] = replace(out[taken], dep="dobj", head=k)
    out[first] = replace(out[first], dep="nsubj", head=k)
    out[k - 1] = replace(out[k - 1], dep="conj", head=first)
    out[k] = replace(out[k], pos="VERB", tag="VBP", lemma=base, dep="ROOT", head=k)
    return out
