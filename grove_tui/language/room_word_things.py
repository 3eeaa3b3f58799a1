"""Things of a room said with a word of the room (round 42).

"The dorm bunks", "the bunks in the dormitory", "the dispensary counter": the room's word then a kind
of thing the room has is that thing, even when a name of the room itself carries the thing's word ("bunk
room", "medicine counter"). "The circle exit", "the exit of the rope hall": the one exit of that room.
"The roped walls": a room said by its name's first word and the kind of its several things is the room."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.places import PlaceEntry, PlaceIndex, PlaceMatch
from grove_tui.language.room_exits import room_exit
from grove_tui.language.tokens import lemma

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

EXIT_HEADS = frozenset({"exit"})


def _kinds(entry: PlaceEntry) -> set[str]:
    return {w for kind in entry.types for w in kind.split()}


def things_of_kind(index: PlaceIndex, head: str, zone: str) -> list[PlaceEntry]:
    """The fixtures of `zone` whose kind (the world's type) holds `head` ("bunk" is no type: their names)."""
    things = [e for e in index.entries if e.kind == "entity" and e.zone == zone]
    return [e for e in things if head in _kinds(e)] or \
        [e for e in things if any(p and p[-1] == head for p in e.phrases)]


def own_word_thing(index: PlaceIndex, head: str, zone: str) -> PlaceMatch | None:
    """The one fixture of `zone` that `head` names, though `head` is also a word of the room's names
    ("bunk" of the "bunk room" with its bunks); None when no fixture or several are so named."""
    found = things_of_kind(index, head, zone)
    return PlaceMatch(found[0].name, "entity", zone, 1.0, True) if len(found) == 1 else None


def exit_of_room(index: PlaceIndex, head: str, zone: str) -> PlaceMatch | None:
    """"The circle exit": the one door out of the building in `zone`, when `head` is "exit"."""
    if head not in EXIT_HEADS:
        return None
    room = next((z for z in index.world.zones if z.name == zone), None)
    exits = [d.name for d in room.doors if d.exit] if room is not None else []
    return PlaceMatch(exits[0], "door", zone, 1.0, True) if len(exits) == 1 else None


def room_by_first_words(index: PlaceIndex, lemmas: Sequence[str], plural: bool) -> PlaceMatch | None:
    """"The roped walls": words that are a room's name without its last word ("roped hall", "roped
    area"), then in the plural the kind of several of that room's fixtures, are that room."""
    if not plural or len(lemmas) < 2 or lemmas[-1] in lx.GENERIC_PLACE_HEADS or lemmas[-1] in lx.DOOR_WORDS:
        return None
    head, before = lemmas[-1], tuple(lemmas[:-1])
    rooms = {e.name for e in index.entries if e.kind == "zone" for p in e.phrases
             if len(p) == len(before) + 1 and p[:-1] == before and (p[-1] in lx.GENERIC_PLACE_HEADS or p[-1] in _kinds(e))}
    if len(rooms) != 1:
        return None
    (zone,) = rooms
    return PlaceMatch(zone, "zone", zone, 1.0, True) if len(things_of_kind(index, head, zone)) >= 2 else None


# Prepositions after which "the circle exit" is a place, not a room and then people who exit it.
_TOWARD = frozenset("to towards toward via through for by near beside past at from".split())


def exit_of_room_said(s: Sentence, phrase: Sequence[str], j: int) -> bool:
    """Whether "exit" at j ends a place phrase naming a room ("to the circle exit", "via the circle
    exit"): the room has one exit, and a preposition of going or of being by a thing comes before it,
    not "in" ("the fans in the circle exit calmly": they leave it)."""
    if s.low[j] != "exit" or not phrase or room_exit(s.index, [*(lemma(w) for w in phrase), "exit"]) is None:
        return False
    x = j - len(phrase) - 1
    while x >= 0 and s.low[x] in lx.DETERMINERS:
        x -= 1
    return x >= 0 and s.low[x] in _TOWARD


_INSIDE = ("in", "inside", "of")


def thing_said_inside(low: Sequence[str], lemmas: Sequence[str], j: int,
                      named: Callable[[Sequence[str], int], tuple[PlaceMatch, int] | None]
                      ) -> tuple[PlaceMatch, int] | None:
    """"The bunks in the dorm", "the counter in the dispensary" when the phrase read took in the
    preposition ("in" is a word of a name of the world) or the room too (the room's "bunk room"): the
    thing of that room, by `named` (the thing's head, the index of the preposition)."""
    if not lemmas:
        return None
    if j >= 1 and low[j - 1] in _INSIDE and j < len(low):
        return named(lemmas, j - 1)  # "the counter in | the dispensary"
    for x in range(j - 2, max(j - 6, 0), -1):
        if low[x] in _INSIDE:
            head = lemma(low[x - 1])
            return named((head,), x) if lemmas[0] == head and len(lemmas) >= 2 else None
    return None
