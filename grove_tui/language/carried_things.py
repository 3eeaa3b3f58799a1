"""Things carried said with a count (round 28): "a trainee takes a handful of used mirrors and probes
to the sterilising room", "a nurse brings a few clean towels to the ward". After a count the reader
takes any plural noun for people ("ten zombies"), and the object of "takes"/"brings" was a second
group led along; the object of a verb of carrying is people only when its noun is a person word
(a list's, a title, or one the reader otherwise knows as people: "a handful of children"), so a
counted object whose noun is none is the things carried."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import verb_lemma

if TYPE_CHECKING:
    from grove_tui.language.counts import Quantifier
    from grove_tui.language.people import People
    from grove_tui.language.sentence import Sentence

# Verbs that take along people or things alike ("takes the children", "takes the files").
_CARRYING = frozenset("take bring carry fetch ferry cart lug haul".split())


def counted_things(s: Sentence, people: People, verb: int, q: Quantifier | None, head: int | None) -> bool:
    """Whether the counted object after the verb at `verb` is things carried, not people led."""
    if q is None or head is None or verb_lemma(s.low[verb]) not in _CARRYING:
        return False
    return not people.is_person_noun(head)


def collective_of_things(s: Sentence, people: People, verb: int, head: int | None) -> bool:
    """Whether the object after the verb of carrying at `verb` is a collective of things: "brings a
    bunch of flowers", "carries a bunch of keys to ...". A collective of people ("a bunch of kids")
    is people led; one whose noun after "of" names no person is the things carried."""
    if head is None or verb_lemma(s.low[verb]) not in _CARRYING or s.lemma(head) not in lx.IMPLIED_RANGES or \
            head + 2 >= s.n or s.low[head + 1] != "of":
        return False
    k = s.skip(head + 2, lx.DETERMINERS)
    while k < s.n and s.w[k].pos == "ADJ" and not people.is_person_noun(k):
        k += 1  # "a bunch of fresh flowers"
    return k < s.n and s.w[k].pos == "NOUN" and not people.is_person_noun(k) and \
        people.person_head(k, counted=False) is None
