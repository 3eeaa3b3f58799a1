"""A plural no list names counted by "a couple of", "a pair of" or "a trio of", the group word the
parser's subject (round 34): "a couple of first-year sketchers put away their pencils", "a pair of
trainee ushers head to the foyer". "Two first-year sketchers put away ..." made the plural the verb's
subject and the people were read; with "a couple of" before it the plural is the object of "of", and
they were lost. The plural is the subject through its group word when that word is the subject of a
verb that is not only a thing's."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence

_GROUP_OF = frozenset("pair trio couple quartet handful dozen score gaggle bunch posse gang".split())


def subject_through_a_group_of(s: Sentence, i: int) -> bool:
    """Whether plural word i is the object of "of" after a group word that is a verb's subject."""
    word = s.w[i]
    if word.dep != "pobj" or s.low[word.head] != "of":
        return False
    group = s.w[word.head].head
    g = s.w[group]
    if s.lemma(group) not in _GROUP_OF or g.dep not in ("nsubj", "nsubjpass") or g.head == group:
        return False
    verb = g.head
    return s.w[verb].pos in ("VERB", "AUX") and s.verb(verb) not in lx.THING_VERBS
