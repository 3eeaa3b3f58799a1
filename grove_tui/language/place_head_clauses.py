"""A bare head that names one place exactly, with a clause that says which of its kind: "the pool where
toddlers have lessons" is the teaching pool, though "the pool" is an alias of the main pool; "the
room where they are sterilised", "the desk where you collect parcels". A place's whole name with more
than its head ("the main pool where ...") is that place, and the clause only says what is done there.
And the converse (round 44): a clause that finds a room, said with a head that is the kind of one of its
fixtures and not the room's ("the counter that does fried chicken" of the chicken shop): that fixture.
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


def fixture_named_by_head(index: PlaceIndex, meant: PlaceMatch, head: str) -> PlaceMatch:
    """The one fixture of a room a clause found whose kind the head says, when the room is not called so
    by its own name: "the counter that does fried chicken" is the chicken shop's counter."""
    room = index.entry(meant.name)
    if room is None or room.kind != "zone" or (room.phrases and room.phrases[0][-1] == head):
        return meant
    fixtures = [e for e in index.entries if e.kind == "entity" and e.zone == room.name and
                ((head,) in e.phrases or head in {w for t in e.types for w in t.split()[-1:]})]
    if len(fixtures) != 1:
        return meant
    return PlaceMatch(fixtures[0].name, fixtures[0].kind, fixtures[0].zone, meant.score, False)
