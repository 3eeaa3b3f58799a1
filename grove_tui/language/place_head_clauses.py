"""A bare head that names one place exactly, with a clause that says which of its kind: "the pool where
toddlers have lessons" is the teaching pool, though "the pool" is an alias of the main pool; "the
room where they are sterilised", "the desk where you collect parcels". A place's whole name with more
than its head ("the main pool where ...") is that place, and the clause only says what is done there.
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.places import PlaceIndex, PlaceMatch
from grove_tui.language.sentence import Sentence


def head_described(s: Sentence, content: Sequence[str], j: int) -> bool:
    """Whether the place phrase ending before word j is its head alone ("the pool"), and a "where"
    clause follows it to say which place of that kind it is."""
    return len(content) == 1 and j + 1 < s.n and s.low[j] == "where"


def room_named_by_head(index: PlaceIndex, meant: PlaceMatch, head: str) -> PlaceMatch:
    """The room a clause's place is in, when the head said is one of the room's own words and none of the
    place's: "the pool where toddlers have lessons" is the teaching pool ("small pool"), not its learner
    tank, a pool only by its type."""
    entry, room = index.entry(meant.name), index.entry(meant.zone)
    if entry is None or room is None or entry.kind == "zone" or any(head in p for p in entry.phrases) or \
            not any(head in p for p in room.phrases):
        return meant
    return PlaceMatch(room.name, room.kind, room.zone, meant.score, False)
