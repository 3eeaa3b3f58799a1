"""A headless "where" clause ("to where everyone eats their lunch", "over to where people sit down")
names a room by what is done in it. Seating people merely use there (the lunch tables, the sofas)
is nearer in words only because its name says the clause's thing ("lunch"), and the room holding it
is the place meant; a desk, a kiosk or a rack where the thing is done or kept stays itself (language/place_meaning.py, `where_clause`)."""

from __future__ import annotations

from grove_tui.language.places import PlaceIndex, PlaceMatch

Decided = tuple[PlaceMatch, float, str, tuple[str, ...]]

_SEATS = frozenset({"seating"})


def room_of_used_fixture(index: PlaceIndex, meant: Decided) -> Decided:
    """The room of the fixture `meant` names when that fixture is seating people use there."""
    match = meant[0]
    if match.kind != "entity":
        return meant
    fixture, room = index.entry(match.name), index.entry(match.zone)
    if fixture is None or room is None or room.kind != "zone" or not fixture.tag_tokens & _SEATS:
        return meant
    return (PlaceMatch(room.name, room.kind, room.name, match.score, False), meant[1],
            f"{meant[2]}; a thing used there, so its room {room.name}", meant[3])
