"""What a purpose is done with, kept in the purpose (round 46): "to help with boarding", "to deal with a
spill", "to lend a hand with the luggage". The purpose's phrase ended at "with", so only "to help" was
kept and what the help is for was lost. A "with" phrase right after the purpose's verb or object that
names no person, no robot and no place of the world is part of the purpose; "to chat with the manager"
(a person) and "to help with the queue at the gate" (the place after it) are left as they were."""

from __future__ import annotations

from collections.abc import Callable

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence


# Words of people a purpose may be done with ("to catch up with them").
_PEOPLE_WORDS = frozenset("him them me us you everyone everybody someone somebody friends".split())


def with_object_end(s: Sentence, end: int, is_person: Callable[[int], bool],
                    names_place: Callable[[int], bool]) -> int:
    """The end (exclusive) of a "with" phrase at `end` that belongs to the purpose before it, else `end`."""
    if end >= s.n or s.low[end] != "with":
        return end
    k = end + 1
    stop = s.phrase_end(k)
    if stop <= k:
        return end
    head = s.skip(k, lx.DETERMINERS)
    for x in range(k, stop):
        if is_person(x) or s.low[x] in lx.ROBOT_WORDS or s.low[x] in _PEOPLE_WORDS or s.lemma(x) in lx.PERSON_NOUNS:
            return end
    if names_place(head):
        return end
    return stop
