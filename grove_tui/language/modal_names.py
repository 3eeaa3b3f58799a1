"""A first name that is also a modal verb: "Will waits in the boardroom", "Grace and Will walk to the
food court", "Will queues at the desk". The small parser tags a capitalised "Will" a modal (MD) and the
verb after it its head, so no one is named and the sentence reads as a vague crowd. A modal is never
followed by a verb in "-s" ("will waits"), and a modal is never capitalised inside a sentence; there the
word is a person's name, the subject of the verb after it (or one of a list of names before that verb).
"""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language.parser import Word
from grove_tui.language.tokens import verb_lemma

MODAL_NAMES = frozenset({"will"})


def _is_name(words: list[Word], k: int) -> bool:
    w = words[k]
    if w.lower not in MODAL_NAMES or w.tag != "MD" or not w.text[:1].isupper() or w.text.isupper():
        return False
    first = k == 0 or words[k - 1].sentence != w.sentence or words[k - 1].pos == "PUNCT" and words[k - 1].lower != ","
    nxt = words[k + 1] if k + 1 < len(words) and words[k + 1].sentence == w.sentence else None
    if not first:
        return True  # "Grace and Will walk": a modal is not capitalised mid-sentence
    return nxt is not None and (nxt.tag == "VBZ" or nxt.lower in ("and", ",") or nxt.tag == "NNS"
                                and verb_lemma(nxt.lower) != nxt.lower)  # "Will waits", "Will and Grace", "Will queues"


def as_modal_names(words: list[Word]) -> list[Word]:
    """The parse with a name taken for a modal ("Will") tagged a proper noun, the subject of its verb."""
    out = list(words)
    for k in range(len(words)):
        if not _is_name(words, k):
            continue
        verb = words[k].head if words[k].head != k else k + 1
        if verb >= len(words):
            continue
        if k >= 2 and words[k - 1].lower == "and" and words[k - 2].pos in ("PROPN", "NOUN") \
                and words[k - 2].text[:1].isupper():
            first = k - 2  # "Grace and Will walk": the first name is the subject, Will its conjunct
            while first >= 2 and words[first - 1].lower == "," and words[first - 2].text[:1].isupper():
                first -= 2
            out[k] = replace(words[k], pos="PROPN", tag="NNP", lemma="will", dep="conj", head=first)
            for j in range(first, k, 2):  # "Grace and Will": the parser's common noun, a name too
                out[j] = replace(out[j], pos="PROPN", tag="NNP", dep="nsubj" if j == first else "conj",
                                 head=verb if j == first else first)
            if words[verb].dep != "ROOT":
                out[verb] = replace(words[verb], dep="ROOT", head=verb)
                for j in range(len(words)):
                    if j != verb and out[j].dep == "ROOT" and out[j].sentence == words[k].sentence:
                        out[j] = replace(out[j], dep="nsubj", head=verb)
            continue
        if words[k].dep == "ROOT":  # "Will queues at ...": the parser's root, the verb its subject
            verb = k + 1
            out = [replace(x, head=verb) if x.head == k and x.i != k else x for x in out]
        out[k] = replace(words[k], pos="PROPN", tag="NNP", lemma="will", dep="nsubj", head=verb)
        if out[verb].pos == "NOUN" and out[verb].lower.endswith("s"):  # "Will queues": the verb taken for a noun
            out[verb] = replace(out[verb], pos="VERB", tag="VBZ", lemma=verb_lemma(out[verb].lower), dep="ROOT", head=verb)
    return out
