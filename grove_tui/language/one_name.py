"""A first name ending in "s" is one person (round 20): "Gladys pops out of the ward", "Charles
strolls over to the pharmacy", "Agnes ambles to the cafe". The reader's lemma strips the "s" as a
plural ("glady"), and a plural with no count is a vague crowd; the parser says better: a capitalised
word it tags a singular proper noun (NNP, not NNPS), or the subject of a verb in the singular
("Agnes wanders"), which no list of the lexicon names as people, is one named person."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence


def one_name(s: Sentence, k: int) -> bool:
    """Whether word k is a singular first name the lemma would read as a plural (module doc)."""
    w = s.w[k]
    low = s.low[k]
    if not w.text[:1].isupper() or not low.endswith("s"):
        return False
    agrees = w.dep == "nsubj" and s.w[w.head].tag == "VBZ"  # "Agnes wanders", though tagged a plural noun
    if not ((w.pos == "PROPN" and w.tag == "NNP") or (w.pos in ("PROPN", "NOUN") and agrees)):
        return False
    if w.text.isupper() or low in lx.PERSON_NOUNS or s.lemma(k) in lx.PERSON_NOUNS:
        return False  # "GPs", "Nurses wait": people in the plural, whatever the tag
    return not s.index.knows(s.lemma(k)) and not s.index.knows(low)
