"""A possessive pronoun said for a room ("she stays put in hers", "the director works late in hers"):
the room of the person named before it when the world names whose room is whose (Mrs Whitfield's
office, by its alias or its description), else the room of the kind of person whose clause it is."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language.described_owners import Decided, named_room
from grove_tui.language.places import PlaceMatch

if TYPE_CHECKING:
    from grove_tui.language.place_phrases import PlacePhrases

_PRONOUN = {"hers": "her", "his": "his", "theirs": "their"}


def elided_owned(places: PlacePhrases, k: int, at: int) -> Decided | None:
    """The room "hers" (word k, after the preposition or verb at `at`) stands for, else None."""
    s = places.s
    pronoun = _PRONOUN.get(s.low[k])
    if pronoun is not None:
        heads = [p.words[-1] for p in places.history if p.match is not None and p.words]
        e = named_room(s, k, pronoun, heads[::-1])
        if e is not None:
            return (PlaceMatch(e.name, e.kind, e.zone, 1.0, False), 0.8, f"'{s.low[k]}': the room of the one named, {e.name}", ())
    return places._owned(("room",), None, places.owner) if places.owner else None
