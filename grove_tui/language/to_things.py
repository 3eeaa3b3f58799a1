"""Going to a thing that is no place, said with where it is: "goes to her post at the poolside", "heads
out to his cab by the lorry park exit", "walks back to their car in the car park". The thing names
nothing of the world, so the place after it ("at the poolside") is where they go, not where they are: its
phrase takes the role of "to"."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence

_TO = frozenset({"to", "towards", "toward", "into"})
_WHERE_IT_IS = frozenset({"at", "by", "in", "on", "near", "beside", "outside", "next"})
_OPENERS = frozenset({"his", "her", "their", "my", "our", "your", "its", "the", "a", "an"})
# At most this many words name the thing ("her usual post", "his battered old cab").
_THING_WORDS = 4


def to_a_thing_before(s: Sentence, at: int) -> bool:
    """Whether the preposition at `at` ("at", "by", ...) follows "to" and a thing no place of the world
    is called, with nothing else between ("to his cab by the exit")."""
    if at < 3 or s.low[at] not in _WHERE_IT_IS:
        return False
    x = at - 1
    nouns: list[int] = []
    while x > 0 and at - x <= _THING_WORDS and s.w[x].pos in ("NOUN", "ADJ") and s.low[x] not in _OPENERS:
        nouns.append(x)
        x -= 1
    if not nouns or s.w[at - 1].pos != "NOUN" or s.low[x] not in _OPENERS or x < 1 or s.low[x - 1] not in _TO:
        return False
    if x >= 2 and s.w[x - 2].tag in ("VBN", "JJ"):
        return False  # "glued to her phone on the benches": no going to the phone
    # the thing names no place of the world ("to her desk by the window" is the desk)
    # nor the robot or a person ("runs up to the robot beside the kiosk": where they meet it)
    return not any(_names_a_place(s, s.lemma(n)) or s.low[n] in lx.ROBOT_WORDS or s.lemma(n) in lx.PERSON_NOUNS
                   for n in nouns)


def _names_a_place(s: Sentence, word: str) -> bool:
    """Whether a place of the world is called by this word, not only by names it modifies: "boat" of
    "boat shop" and "boat trailers" names no place, so "to their boat on pontoon B" goes to pontoon B."""
    if not s.index.knows(word):
        return False
    phrases = [p for e in s.index.entries for p in e.phrases if word in p]
    return not phrases or any(p[-1] == word for p in phrases)
