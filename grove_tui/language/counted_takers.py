"""A verb of taking someone along said after "a pair of" and a plural (round 37): "A pair of orderlies wheel
Mr Ahmed from ward 2 to imaging", "a couple of porters push Mrs Lee to X", "a team of paramedics stretcher
...". The small parser reads "orderlies wheel" as one noun after "of" and hangs the person taken on
"pair", so the takers are lost and the person taken walks alone. A verb of taking the parser made the
noun after "of" (the plural before it its modifier), in a sentence with no verb of its own, followed by
the person taken (a name, a title, an article or a number), is the verb; "a pair of orderlies" its
subject and the person after it its object.
"""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import Word

# Words before "of" that count the people after it.
_COUNTING = frozenset("pair couple trio group team handful few number bunch gang party crew squad band".split())


def _object(words: list[Word], k: int) -> tuple[int, int] | None:
    """The first and last word of the person taken, right after the verb at k: a run of capitalised names
    ("Mr Ahmed") or describing words and a noun ("an injured shopper")."""
    j = k + 1
    while j < len(words) and words[j].sentence == words[k + 1].sentence and (
            words[j].pos in ("DET", "ADJ", "NUM") or (words[j].lower in ("his", "her", "their"))):
        j += 1
    if j >= len(words) or words[j].pos not in ("PROPN", "NOUN") or words[j].sentence != words[k + 1].sentence:
        return None
    last = j
    if words[j].pos == "PROPN":
        while last + 1 < len(words) and words[last + 1].pos == "PROPN" and words[last + 1].text[:1].isupper():
            last += 1
    return k + 1, last


def _one_sentence(words: list[Word], k: int) -> list[Word]:
    """The parse with the sentence the parser began right after word k joined to k's ("a pair of
    attendants wheel | Mr Hale from ...": no stop between them)."""
    if k + 1 >= len(words) or words[k + 1].sentence == words[k].sentence or words[k].pos == "PUNCT":
        return words
    split = words[k + 1].sentence
    return [replace(x, sentence=x.sentence - 1) if x.sentence >= split else x for x in words]


def as_counted_takers(words: list[Word]) -> list[Word]:
    """The parse with "a pair of orderlies wheel X" read as the pair wheeling X (see the module doc)."""
    out = list(words)
    for k, w in enumerate(words):
        if k < 3 or k + 1 >= len(words) or w.pos != "NOUN" or w.tag != "NN" or w.lower not in lx.LEADING_VERBS:
            continue
        plural, of, counter = words[k - 1], words[k - 2], words[k - 3]
        if of.lower != "of" or plural.tag not in ("NNS", "NNPS") or counter.lower not in _COUNTING or \
                len({plural.sentence, of.sentence, counter.sentence, w.sentence}) != 1:
            continue
        taken = _object(words, k)
        if taken is None:
            continue
        first, obj = taken
        words = _one_sentence(out, k)
        out = list(words)
        w = words[k]
        if any(x.pos in ("VERB", "AUX") for x in words[:obj + 1] if x.sentence == w.sentence and x.i != k):
            continue
        inside = set(range(counter.i, obj + 1))
        for j, x in enumerate(words):
            if x.sentence != w.sentence or j in inside:
                continue
            if x.head in inside or x.dep == "ROOT":
                out[j] = replace(out[j], head=k) if x.dep != "ROOT" else replace(out[j], dep="dep", head=k)
        for j in range(counter.i, obj + 1):
            if j < counter.i + 3 or j == k:
                continue
            out[j] = replace(out[j], head=obj, dep="det" if words[j].pos == "DET" else
                             "amod" if words[j].pos == "ADJ" else "compound") if j != obj else out[j]
        out[counter.i] = replace(counter, dep="nsubj", head=k)
        out[of.i] = replace(of, dep="prep", head=counter.i)
        out[plural.i] = replace(plural, dep="pobj", head=of.i)
        for j in range(counter.i):
            if words[j].head == counter.i or words[j].dep == "det":
                out[j] = replace(out[j], head=counter.i)
        out[k] = replace(w, pos="VERB", tag="VBP", lemma=w.lower, dep="ROOT", head=k)
        out[obj] = replace(out[obj], dep="dobj", head=k)
    return out
