"""Nouns after a place preposition that say no place, round 29: people counted after a preposition
("threads its way through forty-odd pickers", "weaves through a dozen pickers": the people the robot
passes, not a room the world lacks; round 44, a collective of them: "weaves through a swarm of
schoolkids", "pushes through a gaggle of hens"), and a handheld device something is done on ("recording it on a
phone", "chatting on a mobile", "taking photos on a tablet") or gathered round ("huddle round a laptop")."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.agent_compounds import agent_of_a_verb
from grove_tui.language.counts import number_at
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma

# Devices held in the hand that something is done on.
DEVICES = frozenset("phone mobile smartphone iphone tablet ipad laptop camera camcorder kindle walkie-talkie "
                    "walkie radio handset headset gopro".split())
# "on a phone", "over the radio"; "huddle round a laptop", "crowd around her phone": a device gathered round
_DEVICE_PREPOSITIONS = frozenset({"on", "onto", "over", "via", "with", "round", "around"})
_COUNT_WORDS = frozenset("dozen dozens score scores hundred hundreds odd -odd or so some about around nearly "
                         "almost over roughly".split())


def no_place_thing(s: Sentence, k: int, prep: str) -> bool:
    """Whether the phrase from k after the preposition `prep` is people counted or a handheld device."""
    return _a_device(s, k, prep) or _counted_people(s, k) or _a_collective_of_people(s, k)


def _a_collective_of_people(s: Sentence, k: int) -> bool:
    """"a swarm of schoolkids", "the small gaggle of hens", "a steady stream of commuters": people."""
    j = k
    while j < s.n and (s.low[j] in lx.DETERMINERS or s.w[j].pos == "ADJ"):
        j += 1
    if j + 2 >= s.n or s.lemma(j) not in lx.IMPLIED_RANGES or s.low[j + 1] != "of":
        return False
    for x in range(j + 2, min(j + 5, s.n)):
        if s.w[x].pos not in ("ADJ", "NOUN", "PROPN", "DET") and s.low[x] != "-":
            return False
        if s.w[x].tag == "NNS" and (s.lemma(x) in lx.PERSON_NOUNS or s.low[x] in lx.PERSON_NOUNS or
                                   (agent_of_a_verb(s.low[x], "") and not s.index.knows(s.lemma(x)))):
            return True
    return False


def _a_device(s: Sentence, k: int, prep: str) -> bool:
    if prep not in _DEVICE_PREPOSITIONS:
        return False
    end = k
    while end < s.n and (s.w[end].pos in ("DET", "ADJ", "NOUN", "PROPN", "PRON") or s.low[end] == "-"):
        end += 1
    return end > k and lemma(s.low[end - 1]) in DEVICES


def _counted_people(s: Sentence, k: int) -> bool:
    j = k
    if j < s.n and s.low[j] in ("a", "an", "the"):
        j += 1
    counted = False
    while j < s.n and (number_at(s, j) is not None or s.low[j] in _COUNT_WORDS or s.low[j] == "-"):
        counted = counted or number_at(s, j) is not None or s.low[j] in ("dozen", "dozens", "score", "hundred",
                                                                          "hundreds")
        j += 1
    while j + 1 < s.n and s.w[j].pos in ("ADJ", "NOUN") and s.w[j + 1].pos in ("ADJ", "NOUN"):
        j += 1  # "a dozen shelf stackers", "forty tired pickers"
    if not counted or j >= s.n or s.w[j].tag != "NNS":
        return False
    said = lemma(s.low[j])
    return said in lx.PERSON_NOUNS or s.low[j] in lx.PERSON_NOUNS or \
        (agent_of_a_verb(s.low[j], "") and not s.index.knows(said))  # "pickers", though no person noun
