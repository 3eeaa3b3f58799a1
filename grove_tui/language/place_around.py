"""The area around a thing, where people stand: "pitch-side", "courtside", "poolside", "by the water".
A thing people cannot stand in or on (the pool's water, a fountain's basin) is not where they are:
the room around it is. Read for language/place_phrases.py."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.places import PlaceIndex, PlaceMatch

_SIDE = "side"
# "-side" words of a place people stand beside, never of a thing a person is at ("bedside", "fireside").
_NOT_AROUND = frozenset({"bed", "fire", "road", "sea", "country", "east", "west", "north", "south", "in", "out",
                         "along", "be", "down", "up", "flip", "off", "on", "back", "front"})
# Prepositions that put people beside a thing, not in it.
_BESIDE = frozenset({"by", "at", "beside", "near", "around", "along", "next", "on"})


def around(index: PlaceIndex, lemmas: Sequence[str]) -> PlaceMatch | None:
    """"pitch-side", "courtside", "the poolside": the zone around the thing or room said before "side";
    None when the phrase is no such word or the world has no such thing."""
    words = [t for t in lemmas if t not in ("the", "-")]
    if not words:
        return None
    if words[-1] == _SIDE and len(words) >= 2:
        thing = words[:-1]
    elif words[-1].endswith(_SIDE) and len(words[-1]) > len(_SIDE) + 2:
        thing = [*words[:-1], words[-1][:-len(_SIDE)]]
    else:
        return None
    if not thing or thing[-1] in _NOT_AROUND:
        return None
    found = index.match(thing)
    if found is None:
        return None
    return PlaceMatch(found.zone, "zone", found.zone, found.score, False)


def beside_thing(index: PlaceIndex, prep: str, match: PlaceMatch | None) -> PlaceMatch | None:
    """A thing of the same kind as the room it fills ("the water" of the pool hall, the pool itself),
    said as where people stand beside it: the room."""
    if match is None or match.kind != "entity" or prep not in _BESIDE:
        return match
    entry, zone = index.entry(match.name), index.entry(match.zone)
    if entry is None or zone is None or not entry.types or entry.types != zone.types:
        return match
    return PlaceMatch(zone.name, "zone", zone.name, match.score, match.exact)


def stairs(index: PlaceIndex, k: int) -> tuple[tuple[PlaceMatch, float, str, tuple[str, ...]], int] | None:
    """"run upstairs", "head downstairs" (the word at k): the world's stairs, where people go up or down,
    and the index after the word; None in a world without stairs (the floor above is no place of it)."""
    for word in ("stairs", "staircase", "stairwell", "escalator", "escalators"):
        found = index.match((word,))
        if found is not None and found.exact:
            return (found, 0.6, f"'upstairs' or 'downstairs': by the stairs, {found.name}", ()), k + 1
    return None
