"""Someone's own person taken along: "the best man pushes the bride's nan in her wheelchair from ...",
"a porter wheels the patient's mum to ...", "a steward walks Tom's grandad back to ...". The object of a
verb of taking along is a person said after a possessor ("the bride's", "Tom's"); the possessor names
who the person belongs to, not who is led, and the phrase was read as no one (the possessor a modifier,
the person after "'s" no subject). The person after "'s" is the one led."""

from __future__ import annotations

from grove_tui.language.people import People
from grove_tui.language.sentence import Sentence

_POSSESSIVE = ("'s", "’s", "'", "’")


def possessed_head(s: Sentence, people: People, start: int) -> int | None:
    """The person word after a possessor that opens the phrase at `start` ("the bride's nan": the
    index of "nan"; "Tom's elderly grandad": of "grandad"), or None."""
    k = start
    while k < s.n and k < start + 3 and s.low[k] not in _POSSESSIVE:
        if s.w[k].pos not in ("NOUN", "PROPN", "ADJ") or s.is_punct(k):
            return None
        k += 1
    if k == start or k + 1 >= s.n or s.low[k] not in _POSSESSIVE:
        return None
    head = people.person_head(k + 1, counted=False)
    return head if head is not None and people.is_person_noun(head) else None
