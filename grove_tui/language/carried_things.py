"""Things carried said with a count (round 28): "a trainee takes a handful of used mirrors and probes
to the sterilising room", "a nurse brings a few clean towels to the ward". After a count the reader
takes any plural noun for people ("ten zombies"), and the object of "takes"/"brings" was a second
group led along; the object of a verb of carrying is people only when its noun is a person word
(a list's, a title, or one the reader otherwise knows as people: "a handful of children"), so a
counted object whose noun is none is the things carried."""

from __future__ import annotations

from typing import TYPE_CHECKING

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
