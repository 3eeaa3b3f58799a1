"""A thing someone works on, said with "a", before the room they are in: "a dresser mends a torn cloak in
the wardrobe", "a porter fixes a squeaky trolley in the basement". Rooms and fixtures are said with
"the" ("mops the corridor", "locks her office"); "a torn cloak" only shares a word with the cloakroom's
alias ("cloaks"), so the place is the one after the preposition, not the object."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence


def made_thing_then_place(s: Sentence, obj: int) -> bool:
    """Whether the object at `obj` opens with "a"/"an" and a place preposition follows its phrase."""
    if obj >= s.n or s.low[obj] not in ("a", "an"):
        return False
    end = s.phrase_end(obj)
    return end < s.n and s.preposition(end) is not None
