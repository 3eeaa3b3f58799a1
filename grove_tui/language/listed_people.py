"""People said as a list of single people before their shared verb: "A keeper and a vet hurry from
the gift shop to the cafe", "a cleaner and a porter wander into ward A". Each "a"/"an" noun of the
list is one person, even when the world names a room by that word ("the vet room", "the keepers'
yard"), since the list's verb is in the plural, a verb people go or stay by, and a place follows it;
a word that names a place by itself, or a thing, is no one."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_ONE = ("a", "an", "one")


def listed_person(s: Sentence, i: int) -> bool:
    """Whether the noun at i is one of "a X and a Y <verb> <place phrase>"."""
    if not (0 < i and s.low[i - 1] in _ONE and _single_noun(s, i)):
        return False
    if i + 3 < s.n and s.low[i + 1] == "and" and s.low[i + 2] in _ONE and _single_noun(s, i + 3):
        verb = i + 4
    elif i >= 4 and s.low[i - 2] == "and" and s.low[i - 4] in _ONE and _single_noun(s, i - 3):
        verb = i + 1
    else:
        return False
    if verb + 1 >= s.n or s.low[verb] != verb_lemma(s.low[verb]):
        return False  # "a keeper and a vet hurry": the plural's verb, not "a gate and a shop hurries"
    going = verb_lemma(s.low[verb]) in lx.INTENT_VERBS or verb_lemma(s.low[verb]) in lx.PEOPLE_GOING_VERBS
    return going and (s.low[verb + 1] in lx.PLACE_PREPOSITIONS or s.w[verb + 1].pos == "ADP")


def _single_noun(s: Sentence, k: int) -> bool:
    """A singular noun that is neither a place by itself nor a thing or the robot."""
    lem = s.lemma(k)
    if lem in lx.PERSON_NOUNS or s.low[k] in lx.PERSON_NOUNS:
        return True  # "a keeper and a cleaner": the parser may take the person for an adjective
    if s.w[k].pos not in ("NOUN", "PROPN") or lem != s.low[k] or lem in lx.NON_PEOPLE or lem in lx.ROBOT_WORDS \
            or lem in lx.CARRYING_THINGS or lem in lx.BUILDING_WORDS or lem in lx.NON_PLACES:
        return False
    match = s.index.match((lem,))
    return match is None or not match.exact
