"""A passive clause whose subject is the people it is done to ("where guests get powdered", "where you
get x-rayed", "where patients are weighed"): said as it was, not turned round into "you powder guests",
which names the people (and so the room named for them) rather than what is done there. The plain
words of the activity ("get powdered": have make-up done) then read it."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma

PEOPLE_PRONOUNS = frozenset("you they we people everyone everybody someone somebody one".split())


def done_to_people(s: Sentence, first: int, aux: int) -> bool:
    """Whether the words from `first` to the passive's auxiliary at `aux` are the people it is done to."""
    words = [w for w in s.low[first:aux] if w not in ("where", "that", "which", "the", "a", "an", "our", "your",
                                                      "their", "all", "most", "some", "new", "young", "little")]
    if not words or len(words) > 2:
        return False
    head = words[-1]
    return head in PEOPLE_PRONOUNS or head in lx.PERSON_NOUNS or lemma(head) in lx.PERSON_NOUNS
