"""One person the lists do not name, told by what the sentence has them do (round 22): a name the
parser tags an adjective at the head of the sentence ("Dorothy pops out of her room"), a noun the
lexicon keeps for a machine that goes along a route of the world ("the dispenser nips out of the
pharmacy into the kitchen": machines do not go from one room to another on their own), and a singular
noun after a word for people ("a locum GP loiters", "an elderly gent makes one cuppa last"), which the
plural-verb guard of `unlisted_people.py` must not take for a verb ("a nervous intern steps aside")."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.place_modifiers import PERSON_ADJECTIVES, names_a_place
from grove_tui.language.weather_nouns import weather_noun

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

# Verbs of going that things do as well ("the trolley rolls from A to B"): no person by the route.
_THINGS_GO = frozenset("roll run fall drop move come go pass arrive leave return travel start stop open close "
                       "break slide tip spill head cross proceed enter exit reach make get drive reverse pull back "
                       "transfer deliver carry commute race dash rush speed rise descend lower lift sink climb fly sail "
                       "ascend".split())
# What water, smoke or light does ("Water pours through the ceiling"): no name opens such a clause.
_FLOWS = frozenset("pour flow leak drip spill seep trickle stream flood gush spread billow waft rise fall "
                   "burst break shine".split())
# Endings of a word for one who does ("dispenser", "florist", "optician").
_DOERS = ("er", "or", "ist", "ian")
_ROUTE_STARTS = frozenset({"from", "of"})
_ROUTE_ENDS = frozenset({"to", "into", "towards", "toward", "onto"})


def leading_name(s: Sentence, i: int) -> bool:
    """Whether word i is a capitalised name opening the sentence, tagged an adjective or a noun, the
    subject of a verb in the singular ("Dorothy pops out ...", "Maureen shuffles along to ...")."""
    w = s.w[i]
    if i != 0 or w.dep != "nsubj" or w.tag not in ("JJ", "NN", "NNP") or not w.text[:1].isupper() or \
            not w.text[1:].islower() or not w.text.isalpha() or (i + 1 < s.n and s.w[i + 1].pos == "NUM"):
        return False  # not "Year 2 walks": a class
    lem = s.lemma(i)
    if any(lem in words for words in (lx.ROBOT_WORDS, lx.STOPWORDS, lx.NON_PEOPLE, lx.DURATION_UNITS, lx.IMPLIED_RANGES,
                                       lx.BUILDING_WORDS, lx.HAZARD_NOUNS)) or names_a_place(s.index, lem):
        return False
    verb = s.w[w.head]
    return verb.pos == "VERB" and verb.tag in ("VBZ", "VBD") and s.verb(w.head) not in _FLOWS and \
        s.verb(w.head) not in lx.THING_VERBS and s.verb(w.head) not in lx.SOUND_LIGHT_VERBS


def goes_along_a_route(s: Sentence, i: int) -> bool:
    """Whether word i, a singular noun opened by "a", "an" or "the" that names no place of the world,
    is the subject of a verb of going from a place into another ("a nursing auxiliary bustles from the
    kitchen into the lounge"); a noun the lexicon keeps for a machine only when it is also a word for
    one who does ("the dispenser nips out of the pharmacy into the kitchen": machines do not go from
    one room to another on their own, and a dog that does is no person)."""
    w = s.w[i]
    if w.dep != "nsubj" or w.pos not in ("NOUN", "ADJ") or w.tag not in ("NN", "JJ") or not s.low[i].isalpha():
        return False
    lem = s.lemma(i)
    if lem in lx.ROBOT_WORDS or lem in lx.STOPWORDS or lem in lx.CARRYING_THINGS or weather_noun(lem) or (
            (lem in lx.NON_PEOPLE or names_a_place(s.index, lem)) and not s.low[i].endswith(_DOERS)):
        return False  # a thing or a place of the world is one who goes only as a word for one who does
    first = _opened_at(s, i)
    if first == 0 or s.low[first - 1] not in ("a", "an", "the"):
        return False
    v = w.head
    verb = s.verb(v)
    if s.w[v].pos != "VERB" or verb in _THINGS_GO or verb in lx.THING_VERBS or verb in lx.SOUND_LIGHT_VERBS:
        return False  # any other verb a route is said with is going: "nips", "scurries", "bustles"
    heads = [j for j in range(v + 1, s.n) if s.w[j].pos == "ADP" and (s.w[j].head == v or s.w[s.w[j].head].head == v)]
    return any(s.low[j] in _ROUTE_STARTS for j in heads) and any(s.low[j] in _ROUTE_ENDS for j in heads)


def by_a_person_adjective(s: Sentence, i: int) -> bool:
    """Whether word i, a singular noun, is the subject of a verb after "a" or "an" and an adjective only
    people are ("an elderly gent lingers", "a retired gent reads"): a person, even where the world has
    a place of the word in the plural ("the gents")."""
    w = s.w[i]
    if w.dep != "nsubj" or w.pos != "NOUN" or w.tag != "NN" or s.w[w.head].pos != "VERB" or \
            s.low[i] in lx.ROBOT_WORDS or s.lemma(i) in lx.NON_PEOPLE:
        return False
    first = _opened_at(s, i)
    return first > 0 and s.low[first - 1] in ("a", "an") and any(s.low[k] in PERSON_ADJECTIVES for k in range(first, i))


def _opened_at(s: Sentence, i: int) -> int:
    first = i
    while first > 0 and s.w[first - 1].head == i and s.w[first - 1].dep in ("amod", "compound", "nmod"):
        first -= 1
    return first


def said_as_a_verb(s: Sentence, i: int) -> bool:
    """Whether subject word i after a word for people may be that person's verb the parser took for a
    noun ("a nervous intern steps aside"): a word in the plural form only."""
    return s.low[i].endswith("s") and not s.low[i].endswith("ss")


_HE_OR_SHE = frozenset({"he", "she", "him", "his", "her", "himself", "herself"})


def told_as_he_or_she(s: Sentence, i: int) -> bool:
    """Whether word i, the singular subject of a verb no list has, opened by "a" or "an", is what a
    "he" or "she" after the verb points back to ("an old dear shrieks when she spots the robot"): a
    person, since no place, thing or animal of the lists is "she"."""
    w = s.w[i]
    if w.dep != "nsubj" or w.pos not in ("NOUN", "ADJ") or w.tag not in ("NN", "JJ") or not s.low[i].isalpha():
        return False
    lem = s.lemma(i)
    if names_a_place(s.index, lem) or lem in lx.NON_PEOPLE or lem in lx.ROBOT_WORDS or lem in lx.STOPWORDS:
        return False
    first = _opened_at(s, i)
    if first == 0 or s.low[first - 1] not in ("a", "an"):
        return False
    v = w.head
    return s.w[v].pos == "VERB" and v > i and any(
        s.low[j] in _HE_OR_SHE for j in range(v + 1, min(s.n, v + 6)))
