"""Someone who moves another person along (round 18): "a keeper wheels a lady ...", "a volunteer
pushes an old gent on a stretcher ...". The small parser may read the verb's "-s" form as a plural
noun the person word modifies ("keeper wheels"), and in a world that names a place after the person
("keepers' yard") nothing else says the word is a person: a singular noun after "a"/"the", then a
verb of taking someone along and a person as its object, is the mover."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.caused_motion import ROUTE_WORDS, taking_verb
from grove_tui.language.led_far import led_far_before
from grove_tui.language.load_carriers import load_carrier
from grove_tui.language.person_carriers import person_carrier
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_OPENERS = frozenset({"a", "an", "the", "his", "her", "their", "our", "my", "its"})
_THINGS = (lx.NON_PEOPLE - lx.PERSON_NOUNS) | lx.ROBOT_WORDS | lx.NON_PLACES | lx.BUILDING_WORDS | lx.CARRYING_THINGS
# Words for people the lexicon's person nouns lack, said of someone moved along ("an elderly gent").
MOVED_PEOPLE = frozenset({"gent", "fella", "fellow", "chap", "bloke", "geezer", "gal", "lass", "lad"})


def mover_subject(s: Sentence, i: int) -> bool:
    """Whether word i is a singular noun after "a"/"the" whose verb, next, takes a person along."""
    if i < 1 or i + 2 >= s.n or s.low[i - 1] not in _OPENERS or not s.low[i].isalpha() or len(s.low[i]) < 3:
        return False
    if s.w[i].pos not in ("NOUN", "PROPN") or s.lemma(i) != s.low[i] or s.lemma(i) in _THINGS:
        return False
    verb = s.low[i + 1]
    if not verb.endswith("s") or verb_lemma(verb) == verb or verb_lemma(verb) not in lx.LEADING_VERBS:
        return False
    return moved_person_at(s, i + 2) is not None


def moved_person_at(s: Sentence, k: int) -> int | None:
    """The person word of an object phrase from k ("a lady", "an elderly gent", "the new starter")."""
    if k >= s.n or (s.low[k] not in _OPENERS and s.w[k].pos != "NUM"):
        return None
    for j in range(k + 1, min(k + 4, s.n)):
        if s.lemma(j) in lx.PERSON_NOUNS or s.low[j] in lx.PERSON_NOUNS or s.low[j] in MOVED_PEOPLE:
            return j
        if s.w[j].pos not in ("ADJ", "NOUN") and s.w[j].tag != "VBN":
            return None
    return None


def moved_person_noun(s: Sentence, i: int) -> bool:
    """Whether word i is a word for a person no list has, moved along by a verb of taking someone
    ("pushes an elderly gent on a gurney"): after a determiner and within three words of the verb."""
    if s.low[i] not in MOVED_PEOPLE:
        return False
    k = i - 1
    while k > 0 and (s.w[k].pos == "ADJ" or s.low[k] in _OPENERS) and i - k <= 3:
        k -= 1
    return k < i - 1 and verb_lemma(s.low[k]) in lx.LEADING_VERBS


# What a person is pushed or carried on or in ("on a gurney", "in a buggy"), not a bed or a chair,
# which may be a place the person is at.
RIDDEN_THINGS = lx.CARRYING_THINGS - {"bed", "chair", "cot", "crib"}


def carried_in(s: Sentence, at: int, lemmas: tuple[str, ...] | list[str]) -> bool:
    """Whether the phrase of a preposition at `at` names what someone moved along rides on ("pushes
    an elderly codger on a gurney"): a thing of riding, after a verb of taking someone along."""
    return bool(lemmas) and lemmas[-1] in RIDDEN_THINGS and \
        (any(verb_lemma(s.low[x]) in lx.LEADING_VERBS for x in range(max(0, at - 6), at)) or taken_in(s, at)
         or led_far_before(s, at)) or load_carrier(s, at, lemmas) or person_carrier(s, at, lemmas)


def taken_in(s: Sentence, at: int) -> bool:
    """Whether the phrase of "in"/"on" at `at` says what someone is taken along in by a verb no list
    has, a route after it ("hustles Edna in her wheelchair out of ward A")."""
    return any(taking_verb(s, x) and s.w[x + 1].pos in ("DET", "PROPN", "NUM") for x in range(max(0, at - 5), at - 1)) \
        and any(s.low[y] in ROUTE_WORDS for y in range(at + 2, min(s.n, at + 7)))


# Verbs of going to get someone, who then comes along ("fetches the new starter from the lobby and
# takes him to ...", "collects the twins from the crèche"): as a verb of taking someone along.
FETCHING_VERBS = frozenset("fetch collect retrieve".split())
_PERSON_PRONOUNS = frozenset({"him", "her", "them"})


def fetched_then_taken(s: Sentence, i: int) -> bool:
    """Whether the noun at i, which no list names as people, is the object of a verb of fetching or
    taking along that the sentence then takes along by a pronoun for people ("fetches the new starter
    from the lobby and takes him to the office"): a person."""
    if s.w[i].pos not in ("NOUN", "PROPN") or not s.low[i].isalpha() or s.lemma(i) in _THINGS:
        return False
    k = i - 1
    while k > 0 and (s.w[k].pos == "ADJ" or s.low[k] in _OPENERS) and i - k <= 3:
        k -= 1
    if k == i - 1 or verb_lemma(s.low[k]) not in FETCHING_VERBS | lx.LEADING_VERBS:
        return False
    sentence = s.w[i].sentence
    for j in range(i + 1, min(s.n - 2, i + 12)):
        if s.w[j].sentence != sentence:
            return False
        if s.low[j] == "and" and verb_lemma(s.low[j + 1]) in lx.LEADING_VERBS and s.low[j + 2] in _PERSON_PRONOUNS:
            return True
    return False
