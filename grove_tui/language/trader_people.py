"""A trade's word that the world also gives a room ("the hairdresser", "a florist", "the chemist":
the hair salon, the florist's shop) is one person when it is the subject of a verb of going in the
singular ("the hairdresser goes from the salon to the lounge"): a room does not go anywhere. Without
this the word was only a place's, the sentence named nobody, and the unnamed crowd (3-6) went instead."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_ARTICLES = frozenset({"the", "a", "an"})
# Agent endings a trade's word has: "-er" (hairdresser, barber), "-ist" (florist, chemist), "-ent"
# (newsagent), "-ian" (optician).
_TRADE_SUFFIXES = lx.AGENT_SUFFIXES + ("ent",)


def trader_subject(s: Sentence, i: int) -> bool:
    """Whether word i is a place's word of agent form said as one going person: "the/a/an", the
    word as a singular noun, and right after it (or as its parsed head) a verb of going in "-s"."""
    word = s.w[i]
    if word.pos not in ("NOUN", "PROPN") or word.tag not in ("NN", "NNP") or i == 0 or s.low[i - 1] not in _ARTICLES:
        return False
    lem = s.lemma(i)
    if not (lem.isalpha() and len(lem) >= 5 and lem.endswith(_TRADE_SUFFIXES) and s.index.knows(lem)):
        return False
    if lem in lx.ROBOT_WORDS or lem in lx.NON_PEOPLE or lem in lx.HAZARD_NOUNS:
        return False
    verb = i + 1
    if verb >= s.n or s.w[verb].tag != "VBZ":
        return False
    if word.dep != "nsubj" or word.head != verb:
        return False
    lemma = verb_lemma(s.low[verb])
    if lemma == "be" or s.low[verb] == "is":  # "the hairdresser is in the salon": someone there
        return verb + 1 < s.n and s.preposition(verb + 1) is not None
    return lemma in lx.PEOPLE_GOING_VERBS or lemma in lx.INTENT_VERBS or lemma == "go"
