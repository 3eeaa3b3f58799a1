"""Someone moved along, said by a word no list has but with an adjective only people are (round 35):
"an usher wheels an elderly patron to the front row", "a porter pushes a frail regular to the lift",
"a steward wheels an injured punter out": a person, taken along by the one who moves them."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.place_modifiers import PERSON_ADJECTIVES
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_OPENERS = frozenset({"a", "an", "the", "his", "her", "their", "our", "my"})
_THINGS = (lx.NON_PEOPLE - lx.PERSON_NOUNS) | lx.ROBOT_WORDS | lx.CARRYING_THINGS
# Verbs of moving a person along who cannot go alone; "carries", "leads", "walks" take pets too
# ("carries a sleepy spaniel", "walks a nervous greyhound").
_MOVING_VERBS = frozenset("wheel push escort usher help steer accompany guide trundle".split())


def moved_described_person(s: Sentence, i: int) -> bool:
    """Whether word i, a singular noun, is the object of a verb of taking someone along and said with
    an adjective only people are ("wheels an elderly patron"): a person."""
    w = s.w[i]
    if w.pos != "NOUN" or w.tag != "NN" or not s.low[i].isalpha() or s.lemma(i) in _THINGS or \
            s.index.knows(s.lemma(i)):
        return False
    k = i - 1
    described = False
    while k > 0 and i - k <= 3 and (s.w[k].pos == "ADJ" or s.low[k] in PERSON_ADJECTIVES):
        described = described or s.low[k] in PERSON_ADJECTIVES
        k -= 1
    if not described or s.low[k] not in _OPENERS or k == 0:
        return False
    return verb_lemma(s.low[k - 1]) in _MOVING_VERBS
