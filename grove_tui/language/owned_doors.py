"""A door named by whose it is ("the Hokusai show's emergency door", "the supermarket's exit", "the
canteen's side door"): the owner before the possessive names a room (by its name, or by a thing in it), and
the door is one of that room's own doors: its exit for an emergency, fire or exit word, else the one its words
fit, else its only door. Not the room, and not the thing the owner's words name."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.places import PlaceIndex, PlaceMatch

POSSESSIVES = ("'s", "’s", "'", "’")
EXIT_WORDS = frozenset({"emergency", "fire", "exit", "evacuation"})


def door_of_owner(index: PlaceIndex, low: Sequence[str], lemmas: Sequence[str], j: int
                  ) -> tuple[PlaceMatch, int] | None:
    """The door of the room a possessive names, and the index after the phrase (`j`); None if not so said."""
    if len(lemmas) < 2 or lemmas[-1] not in lx.DOOR_WORDS:
        return None
    start, seen = j, 0
    while start > 0 and seen < len(lemmas):
        start -= 1
        if low[start] not in POSSESSIVES:
            seen += 1
    marks = [x for x in range(start, j) if low[x] in POSSESSIVES]
    if len(marks) != 1:
        return None
    split = sum(1 for x in range(start, marks[0]) if low[x] not in POSSESSIVES)
    owner, door = tuple(lemmas[:split]), tuple(lemmas[split:])
    if not owner or not door:
        return None
    found = index.match(owner)
    if found is None or not found.exact:
        return None  # "the print show's": no room's or thing's own name
    zone = found.name if found.kind == "zone" else found.zone
    doors = [e for e in index.entries if e.kind == "door" and e.zone == zone]
    if not doors:
        return None
    named = [m for m in index.candidates(door) if m.kind == "door" and m.exact]
    if named and all(m.zone != zone for m in named):
        return None  # "the gallery's emergency exit": a door of the world by its own name, read as such
    fitting = [m for m in index.candidates(door) if m.kind == "door" and m.zone == zone]
    exits = [e for e in doors if e.exit]
    if set(door) & EXIT_WORDS and len(exits) == 1:
        chosen = exits[0].name
    elif fitting and (fitting[0].exact or len(fitting) == 1 or fitting[0].score > fitting[1].score + 1e-9):
        chosen = fitting[0].name
    elif len(doors) == 1:
        chosen = doors[0].name
    else:
        return None
    return PlaceMatch(chosen, "door", zone, 1.0, True), j
