"""A way out said by the room it is in: "the ninja course fire door", "the party room emergency exit",
"the sports bar fire exit". The world calls the door something else ("ninja course fire exit", "bar
fire exit"), so the words match the room best and the reader would send people *through* the room;
the phrase names the room's own way out to the outside, which is where people go."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.places import PlaceIndex, PlaceMatch

# the words that end such a phrase: a kind of way out, said with or without what it is for
_KINDS = frozenset("door exit doorway".split())
_FOR = frozenset("fire emergency".split())


def room_exit(index: PlaceIndex, phrase: Sequence[str]) -> PlaceMatch | None:
    """The way out to the outside of the room the phrase names before "fire door" / "emergency exit"
    ("the ninja course fire door"), or None when the phrase is not one or the room has no one exit."""
    from grove_tui.language.places import PlaceMatch

    words = [t for t in phrase if t]
    plain = len(words) >= 2 and words[-1] == "exit" and words[-2] not in _FOR  # "the circle exit" (round 42)
    if not plain and (len(words) < 3 or words[-1] not in _KINDS or words[-2] not in _FOR):
        return None
    room_words = words[:-1] if plain else words[:-2]
    while room_words and room_words[0] in ("the", "a", "an", "its", "their"):
        room_words = room_words[1:]
    if not room_words:
        return None
    found = index.candidates(room_words)
    if not found or found[0].kind != "zone" or not found[0].exact:
        return None
    zone = found[0].name
    exits = [e for e in index.entries if e.kind == "door" and e.exit and e.zone == zone]
    if len(exits) > 1:
        exits = [e for e in exits if e.tokens & _FOR] or exits
    if len(exits) != 1:
        return None
    door = exits[0]
    # above every place the whole phrase names ("emergency exit" is another room's alias), so none ties with it
    best = max((m.score for m in index.candidates(words)), default=0.0)
    return PlaceMatch(door.name, door.kind, door.zone, round(max(best, found[0].score) + 1.0, 4), True)
