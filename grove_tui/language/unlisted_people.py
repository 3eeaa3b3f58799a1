"""A person no list names, told by how the sentence names them: "an airline rep waits", "two
roadies wander", "Little Tom runs". A noun phrase that opens with "a", "an", "the" or a number, or
a capitalised name with no determiner, whose head is the subject of a verb of going, staying or
doing what people do, and names no place, thing, animal, time or the robot, is people: a singular
one is one person, a counted one that many."""

from __future__ import annotations

from functools import lru_cache
from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.modal_names import MODAL_NAMES
from grove_tui.language.and_a_person import hanging_about, joined_lone_subject
from grove_tui.language.aspect_verbs import governed_verb
from grove_tui.language.hazard_subjects import hazard_verb
from grove_tui.language.lone_person import leading_name, said_as_a_verb
from grove_tui.language.place_modifiers import PERSON_ADJECTIVES, names_a_place
from grove_tui.language.tokens import verb_lemma
from grove_tui.language.weather_nouns import weather_noun

if TYPE_CHECKING:
    from grove_tui.language.places import PlaceIndex
    from grove_tui.language.sentence import Sentence

_OPENERS = frozenset({"a", "an", "the"})
# A person's own ("its worried owner waits", "her chaperone waits"): read as "a".
_POSSESSIVES = frozenset({"its", "his", "her", "their", "my", "our", "your"})
# Verbs of going that things do as well ("the cake arrives", "the bus leaves"): with these a noun in
# no list is people only when a name or counted.
_THINGS_GO_TOO = frozenset("arrive leave come go pass move return run start stop open close fall drop roll enter "
                           "exit travel cross get make reach board".split())
# Words that make a name a child's ("Little Tom", "baby Ava").
CHILD_NAME_WORDS = frozenset({"little", "baby", "young", "wee"})


def _people_verb(s: Sentence, head: int) -> bool:
    head = governed_verb(s, head)  # "Stan keeps following it": what he does is following
    verb = s.verb(head)
    return s.w[head].pos == "VERB" and verb not in lx.THING_VERBS and (
        verb in lx.INTENT_VERBS or verb in lx.HUMAN_SUBJECT_VERBS or verb in lx.PEOPLE_GOING_VERBS
        or verb in lx.LEADING_VERBS)  # "an auxiliary wheels Mrs Bello"


# Words after a verb the lexicon lacks that say it is a way of going, said of a name ("Sam waddles
# after the robot"; not "an HGV reverses into bay 2").
_GOING_AFTER = frozenset("after to towards toward into over across along up down round around through past behind "
                         "off away back out".split())


def going_by_way(s: Sentence, v: int) -> bool:
    """Whether verb v, one the lexicon lacks, is a way of going by the word after it."""
    return verb_lemma(s.low[v]) == s.low[v] and v + 1 < s.n and s.low[v + 1] in _GOING_AFTER


def _a_thing(s: Sentence, lem: str) -> bool:
    return (names_a_place(s.index, lem) or lem in lx.ROBOT_WORDS or lem in lx.NON_PLACES or lem in lx.NON_PEOPLE
            or lem in lx.BUILDING_WORDS or lem in lx.DURATION_UNITS or lem in lx.HAZARD_NOUNS
            or lem in lx.IMPLIED_RANGES or lem in lx.STOPWORDS - MODAL_NAMES or lem in lx.COMPOUND_THINGS or lem in lx.PERSON_THINGS
            or weather_noun(lem))  # "the wind rips the side of the tent": weather, nobody


_GROUP_NOUNS = lx.TOGETHER_COLLECTIVES | lx.QUEUE_COLLECTIVES | lx.QUANTIFYING_COLLECTIVES


def _short_name(s: Sentence, i: int) -> bool:
    """A two-letter first name ("Jo", "Al", "Ed"): capitalised, tagged a name, no title."""
    text = s.w[i].text
    return len(text) == 2 and text[0].isupper() and text[1].islower() and s.w[i].tag == "NNP" and \
        s.low[i] not in lx.TITLES and s.low[i] not in lx.STOPWORDS


def unlisted_subject(s: Sentence, i: int) -> bool:
    """Whether word i heads a subject phrase naming people no list has (see the module doc)."""
    word = s.w[i]
    if joined_lone_subject(s, i, lambda lem: _a_thing(s, lem)):
        return True  # "..., and a postdoc hangs about by ...": the parser's adjective and plural noun
    # (A subject the parser tags an adjective is a noun it does not know: "a nervous postgrad leaves".)
    if word.pos not in ("NOUN", "PROPN", "ADJ") or word.dep != "nsubj" or word.head == i or \
            not s.low[i].isalpha() or (len(s.low[i]) < 3 and not _short_name(s, i)):
        return False
    if hazard_verb(s, word.head):
        return False  # "Fat flares up on the grill", "Butter catches fire": a thing on fire, nobody
    if not (_people_verb(s, word.head) or hanging_about(s, word.head) or (going_by_way(s, word.head) and word.tag == "NNP" and (
            i == 0 or s.low[i - 1] not in _OPENERS))):
        if s.verb(word.head) in _GROUP_NOUNS:
            return False  # "Small groups of two chat ...": a group, the parser's verb a noun
        if word.tag != "NNP" or not s.w[i].text[:1].isupper() or not s.w[i].text[1:].islower() or \
                s.w[word.head].tag != "VBZ":
            # "Sarah scurries to the kitchen": a name opening the sentence (tagged a name or, mistaken, an
            # adjective; not a noun: "Lightning strikes nearby"), any verb of hers
            return word.tag in ("NNP", "JJ") and leading_name(s, i)
        # a name, any verb of hers in the singular: "our intern Bella dawdles by the printer"
    if _a_thing(s, s.lemma(i)) or _a_thing(s, s.low[i]):
        return False
    first = i
    while first > 0 and first - 1 < s.w[first - 1].head <= i and (s.joins(first - 1) or s.w[first - 1].dep in ("compound", "amod", "nmod")
                                                      and s.w[first - 1].pos in ("NOUN", "PROPN", "ADJ")):
        first -= 1  # "an airline rep", "two burly roadies", "some 20 well-wishers"
    if any(s.low[k] in lx.ROBOT_WORDS for k in range(first, i)):
        return False  # "the robot hums ...": the robot's verb, tagged a noun
    if word.tag != "NNP" and said_as_a_verb(s, i) and \
            any(s.low[k] in lx.PERSON_NOUNS or s.lemma(k) in lx.PERSON_NOUNS for k in range(first, i)):
        return False  # "a nervous intern steps aside": the person is named before, the verb mistagged
    before = s.low[first - 1] if first > 0 else ""
    if first > 0 and s.w[first - 1].pos == "NUM" and first <= s.w[first - 1].head <= i:
        return True  # "two roadies wander", "3 roadies leave"
    if any(s.low[k] in PERSON_ADJECTIVES for k in range(first, i)):
        return before in _OPENERS or before in _POSSESSIVES  # "a nervous witness leaves", "its worried owner"
    if before in _OPENERS or before in _POSSESSIVES:
        return s.verb(word.head) not in _THINGS_GO_TOO if before != "the" else \
            s.verb(word.head) in lx.HUMAN_SUBJECT_VERBS  # "the cake arrives": a thing
    # A name: capitalised, with no determiner, the phrase opening the sentence or after a comma.
    return leading_name(s, i) or (word.tag == "NNP" and s.w[i].text[:1].isupper() and s.w[i].text[1:].islower()
            and (first == 0 or s.is_punct(first - 1) or s.low[first - 1] in ("and", "while", "as", "then")))


# Verbs whose object is always people ("escorts a shoplifter"): pushing, carrying or wheeling take
# things too ("wheels a trolley"), so they are not here.
_PEOPLE_ONLY_OBJECTS = frozenset("escort accompany usher shepherd chaperone frogmarch guide lead".split())


def unlisted_escorted(s: Sentence, i: int) -> bool:
    """Whether word i heads the object of a verb that takes only people, said by a person ("a guard
    escorts a shoplifter", "a steward ushers two latecomers"): people no list has."""
    word = s.w[i]
    if word.pos not in ("NOUN", "PROPN") or word.dep != "dobj" or word.head == i or not s.low[i].isalpha() or \
            s.verb(word.head) not in _PEOPLE_ONLY_OBJECTS or _a_thing(s, s.lemma(i)) or _a_thing(s, s.low[i]):
        return False
    first = i
    while first > 0 and s.w[first - 1].head == i and s.w[first - 1].dep in ("amod", "compound") and \
            s.w[first - 1].pos in ("ADJ", "VERB", "NOUN"):
        first -= 1  # "escort a handcuffed smuggler", "usher two unruly fans"
    before = s.low[first - 1] if first > 0 else ""
    return before in _OPENERS or (first > 0 and s.w[first - 1].pos == "NUM") or before in ("his", "her", "their")


@lru_cache(maxsize=32)
def _name_pairs(index: PlaceIndex) -> frozenset[tuple[str, str]]:
    return frozenset((a, b) for e in index.entries for p in e.phrases for a, b in zip(p, p[1:]))


def names_a_place_with_next(s: Sentence, k: int) -> bool:
    """Whether a singular person word and the base form after it are two words of one of the world's
    names ("by the host stand", "at the concierge desk"): a place, since a singular person would say
    "stands"."""
    return (k + 1 < s.n and s.low[k] == s.lemma(k) and s.low[k + 1] == s.lemma(k + 1)
            and (s.low[k], s.low[k + 1]) in _name_pairs(s.index))
