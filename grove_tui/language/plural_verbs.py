"""Verbs the small parser takes for a singular noun after people in the plural (round 22): "some 30
well-wishers drift out of the boardroom", where "drift" is read as the sentence's noun and its subject
a word no list has. A word the parser makes the root noun of its sentence, whose own subject is the
plural noun right before it (or a plural the parser makes its modifier), and which the lexicon knows as a verb of what people do, followed by a
preposition, an adverb or the end, is the plural's verb. So is a verb of taking someone along the parser
makes a modifier between a plural and a name ("two carers wheel Mr Reid out of ...", round 23). A singular noun the parser makes a modifier
of the verb right after it ("the hairdresser scoots over"), which has no subject, is its subject."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import Word

_AFTER = frozenset({"ADP", "ADV", "PART", "PUNCT", "SCONJ", "CCONJ"})
_PHRASE_DEPS = frozenset({"nummod", "det", "quantmod", "amod", "compound", "punct", "advmod", "nmod"})


def _people_verb(low: str) -> bool:
    return low in lx.INTENT_VERBS or low in lx.PEOPLE_GOING_VERBS or low in lx.HUMAN_SUBJECT_VERBS


def as_plural_verbs(words: list[Word]) -> list[Word]:
    """The parse with the verb of people in the plural, taken for a noun, tagged a verb (module doc)."""
    out = list(words)
    for k, w in enumerate(words):
        if k > 0 and w.pos == "VERB" and w.tag == "VBZ" and w.dep == "ROOT" and words[k - 1].dep == "compound" and \
                words[k - 1].head == k and words[k - 1].tag == "NN" and \
                not any(x.dep == "nsubj" and x.head == k for x in words if x.sentence == w.sentence):
            out[k - 1] = replace(words[k - 1], dep="nsubj")  # "the hairdresser scoots": its subject, no modifier
            continue
        if _taking_verb_in_a_compound(words, k):  # "two carers wheel Mr Reid out of ...": no noun "wheel"
            root = next((x.i for x in words if x.sentence == w.sentence and x.dep == "ROOT"), k)
            out[k] = replace(w, pos="VERB", tag="VBP", lemma=w.lower, dep="ROOT", head=k)
            out[k - 1] = replace(out[k - 1], dep="nsubj", head=k)
            out[root] = replace(out[root], dep="dobj", head=k) if root != k else out[root]
            continue
        if k == 0 or w.pos != "NOUN" or w.tag != "NN" or w.dep != "ROOT" or not _people_verb(w.lower):
            continue
        prev = words[k - 1]
        nxt = words[k + 1] if k + 1 < len(words) and words[k + 1].sentence == w.sentence else None
        if prev.dep not in ("nsubj", "compound") or prev.head != k or prev.tag not in ("NNS", "NNPS") or \
                (nxt is not None and nxt.pos not in _AFTER):
            continue  # "day-trippers drift from ...": the plural taken for a modifier of "drift", too
        if any(x.dep == "nsubj" and x.head == k for x in words[:k - 1]):
            continue  # "the bell rings at five, 40 visitors stroll": the parser's tree is too far off to mend
        out[k] = replace(w, pos="VERB", tag="VBP", lemma=w.lower)
        out[k - 1] = replace(out[k - 1], dep="nsubj")
        j = k - 2
        while j >= 0 and words[j].sentence == w.sentence and words[j].dep in _PHRASE_DEPS and \
                (words[j].dep != "punct" or words[j].tag == "HYPH"):
            if words[j].head == k:  # "some 40 holiday-makers": the count is the plural's, not the verb's
                out[j] = replace(words[j], head=k - 1)
            j -= 1
    return out


def _taking_verb_in_a_compound(words: list[Word], k: int) -> bool:
    """Whether word k, a verb of taking someone along the parser made a modifier between a plural and
    its object ("carers wheel Mr Reid"), is the plural's verb: no verb in its sentence, a determiner,
    a name or a number after it."""
    w = words[k]
    if k == 0 or k + 1 >= len(words) or w.pos != "NOUN" or w.tag != "NN" or w.dep != "compound" or \
            w.lower not in lx.LEADING_VERBS or words[k - 1].tag not in ("NNS", "NNPS"):
        return False
    nxt = words[k + 1]
    return nxt.sentence == w.sentence and nxt.pos in ("DET", "PROPN", "NUM") and \
        not any(x.pos == "VERB" for x in words if x.sentence == w.sentence)
