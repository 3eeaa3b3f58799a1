"""A headless "where" clause ("to where everyone eats their lunch", "over to where people sit down")
names a room by what is done in it. A fixture is meant only when it is where people are served or
queue (a desk, a counter, a saw cut to order); a fixture people merely use there (the lunch tables, the
sofas) is nearer in words only because its name says the clause's thing, and the room holding it
is the place meant (language/place_meaning.py, `where_clause`)."""

from __future__ import annotations

from grove_tui.language.places import PlaceIndex, PlaceMatch

Decided = tuple[PlaceMatch, float, str, tuple[str, ...]]

_SERVED = frozenset({"service", "queue"})


def room_of_used_fixture(index: PlaceIndex, meant: Decided) -> Decided:
    """The room of the fixture `meant` names when that fixture is not a service or queue point."""
    match = meant[0]
    if match.kind != "entity":
        return meant
    fixture, room = index.entry(match.name), index.entry(match.zone)
    if fixture is None or room is None or room.kind != "zone" or fixture.tag_tokens & _SERVED:
        return meant
    return (PlaceMatch(room.name, room.kind, room.name, match.score, False), meant[1],
            f"{meant[2]}; a thing used there, so its room {room.name}", meant[3])
