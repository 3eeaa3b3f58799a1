"""One person said by a title or a name and known by "his" or "her" after the verb ("The Dean leaves
his vestry", "come closing time Sandra Cole makes her way out of her office", "the Provost strolls
over to his car"): a singular subject that no list names, opened by "the" or said as a capitalised
name, whose own clause goes on with "his", "her", "himself" or "herself", is one person: no place,
thing or animal of the lists is "his" or "her"."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.place_modifiers import names_a_place
from grove_tui.language.sentence import Sentence

_HIS_OR_HER = frozenset({"his", "her", "himself", "herself"})


def subject_of_his_or_her(s: Sentence, i: int) -> bool:
    """Whether word i is the singular subject a "his"/"her" of its own clause points back to."""
    w = s.w[i]
    if w.dep not in ("nsubj", "nsubjpass") or w.pos not in ("NOUN", "PROPN") or w.tag not in ("NN", "NNP"):
        return False
    if not s.low[i].isalpha() or len(s.low[i]) < 3:
        return False
    lem = s.lemma(i)
    if names_a_place(s.index, lem) or s.index.knows(lem) or s.index.knows(s.low[i]) or lem in lx.NON_PEOPLE \
            or lem in lx.ROBOT_WORDS or lem in lx.STOPWORDS or lem in lx.NON_PLACES or lem in lx.BUILDING_WORDS \
            or lem in lx.HAZARD_NOUNS or lem in lx.DURATION_UNITS:
        return False
    first = i
    while first > 0 and s.w[first - 1].dep == "compound" and s.w[first - 1].head == i and s.w[first - 1].pos == "PROPN":
        first -= 1  # "Sandra Cole": the first name before the surname
    named = w.pos == "PROPN" and all(s.w[k].text[:1].isupper() for k in range(first, i + 1))
    opened = first > 0 and s.low[first - 1] == "the"
    if not (named or opened):
        return False
    v = w.head
    if v <= i or s.w[v].pos not in ("VERB", "AUX"):
        return False
    for j in range(v + 1, min(s.n, v + 7)):
        if s.low[j] in (".", ";", "while", "as", "when", "and") or s.w[j].dep in ("nsubj", "nsubjpass"):
            return False  # another clause, and another's "his"
        if s.low[j] in _HIS_OR_HER:
            return True
    return False
