"""One person told by an adjective only people are for their life, age or looks ("a retired farmer
finally goes up to counter 2", "a bearded trucker waits by the kiosk", "a widowed baker sits in the
lounge"): a singular noun after "a", "an" or "the" and such an adjective, the subject of a verb, is a
person, though no list names the noun (the lists' adjectives of feeling are `PERSON_ADJECTIVES`)."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.place_modifiers import names_a_place
from grove_tui.language.sentence import Sentence

LIFE_ADJECTIVES = frozenset((
    "retired widowed bearded moustached balding bald grey-haired white-haired red-haired middle-aged teenage "
    "unemployed married divorced pensioned silver-haired freckled tattooed wrinkled stooped hunched "
    "sunburnt sunburned pigtailed veiled turbaned bespectacled barefoot toothless").split())


def by_a_life_adjective(s: Sentence, i: int) -> bool:
    """Whether the singular noun at i is the subject of a verb after a determiner and a life adjective."""
    w = s.w[i]
    if w.dep != "nsubj" or w.pos not in ("NOUN", "PROPN") or w.tag not in ("NN", "NNP") or not s.w[i].text.islower() \
            or w.head == i or s.w[w.head].pos != "VERB":
        return False
    lem = s.lemma(i)
    if lem in lx.ROBOT_WORDS or lem in lx.NON_PEOPLE or lem in lx.NON_PLACES or names_a_place(s.index, lem):
        return False
    first = i
    while first > 0 and s.w[first - 1].head == i and s.w[first - 1].dep in ("amod", "compound", "nmod", "punct"):
        first -= 1
    if first == 0 or s.low[first - 1] not in ("a", "an", "the"):
        return False
    said = {s.low[k] for k in range(first, i)} | {"-".join(s.low[k:k + 3:2]) for k in range(first, i - 1)
                                                 if s.low[k + 1] == "-"}
    return bool(said & LIFE_ADJECTIVES)
