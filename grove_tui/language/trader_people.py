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
    # the parser may take the word for an adjective of the verb it calls a noun ("the newsagent walk")
    joined = word.pos in ("NOUN", "PROPN", "ADJ") and i > 0 and s.low[i - 1] in _ARTICLES and _coordinated_going(s, i)
    if not joined and (word.pos not in ("NOUN", "PROPN") or word.tag not in ("NN", "NNP") or i == 0 or
                       s.low[i - 1] not in _ARTICLES):
        return False
    lem = s.lemma(i)
    if not (lem.isalpha() and len(lem) >= 5 and lem.endswith(_TRADE_SUFFIXES) and s.index.knows(lem)):
        return False
    if lem in lx.ROBOT_WORDS or lem in lx.NON_PEOPLE or lem in lx.HAZARD_NOUNS:
        return False
    if joined:
        return True
    verb = i + 1
    if verb >= s.n or s.w[verb].tag != "VBZ":
        return False
    if word.dep != "nsubj" or word.head != verb:
        return False
    lemma = verb_lemma(s.low[verb])
    if lemma == "be" or s.low[verb] == "is":  # "the hairdresser is in the salon": someone there
        return verb + 1 < s.n and s.preposition(verb + 1) is not None
    return lemma in lx.PEOPLE_GOING_VERBS or lemma in lx.INTENT_VERBS or lemma == "go"


def _person_word(s: Sentence, k: int) -> bool:
    return s.lemma(k) in lx.PERSON_NOUNS or s.low[k] in lx.PERSON_NOUNS or s.low[k] in lx.KIN_NAMES


def _going_together(s: Sentence, k: int) -> bool:
    """Whether word k is a verb of going or staying said of more than one ("wait", "head")."""
    lemma = verb_lemma(s.low[k])
    return k < s.n and s.low[k] == lemma and (lemma in lx.PEOPLE_GOING_VERBS or lemma in lx.INTENT_VERBS)


def _coordinated_going(s: Sentence, i: int) -> bool:
    """The trade's word joined by "and" to a person, the two the subject of one verb of going or
    staying (round 71): "the hairdresser and a resident wait in the salon", "a resident and the
    hairdresser wait"."""
    if i + 1 < s.n and s.low[i + 1] in ("and", "&"):
        for k in range(i + 2, min(s.n, i + 6)):
            if _person_word(s, k):
                return k + 1 < s.n and _going_together(s, k + 1)
        return False
    return i >= 3 and s.low[i - 2] in ("and", "&") and _person_word(s, i - 3) and i + 1 < s.n and \
        _going_together(s, i + 1)
