"""A thing given by what it is next to: "the bench opposite the big painting", "the tables near the
piano", "the bench next to the water fountain". Of the world's things of that kind, the one in the
landmark's room, or else the nearest to it, is meant; read for language/place_of_zone.py.

Round 72: a part of a room said with "at" ("the chairs at the back of the prayer hall", "the tables at the
far end of the café") places the thing in that room as "near" does."""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.places import PlaceIndex, PlaceMatch
from grove_tui.language.tokens import phrase_lemmas

# Words that place a thing by another, and the words that may follow them before the landmark.
RELATION_WORDS = frozenset("opposite facing beside near nearest closest next behind across by under alongside".split())
_LINKS = frozenset("to from of front the a an that this".split())
# Parts of a room after "at the": "at the back of", "at the far end of".
_PARTS = frozenset("back front end rear side corner top bottom".split())


def _at_part_of(low: Sequence[str], j: int) -> int | None:
    """The index after "at the (far) back/end ... of" at j; None when not so said."""
    k = j + 1
    while k < len(low) and low[k] in ("the", "far", "very", "near"):
        k += 1
    if k + 1 < len(low) and low[k] in _PARTS and low[k + 1] == "of" and k > j + 1:
        return k + 2
    return None


def _point(index: PlaceIndex, name: str) -> tuple[float, float] | None:
    for zone in index.world.zones:
        for entity in zone.entities:
            if entity.name == name:
                return float(entity.interaction_point[0]), float(entity.interaction_point[1])
        for door in zone.doors:
            if door.name == name:
                return float(door.position[0]), float(door.position[1])
    return None


def by_landmark(index: PlaceIndex, low: Sequence[str], lemmas: Sequence[str], j: int,
                words: Callable[[int], tuple[list[str], int]]) -> PlaceMatch | None:
    """The thing of the kind the phrase names (`lemmas`, ending at word j) that the landmark after a
    relation word ("opposite the big painting") is in the room of, or nearest to; None when the kind
    is one thing only, or no landmark follows."""
    part_end = _at_part_of(low, j) if j < len(low) and low[j] == "at" else None
    if j >= len(low) or (low[j] not in RELATION_WORDS and part_end is None) or not lemmas:
        return None
    if low[j] == "in" and not (j + 1 < len(low) and low[j + 1] == "front"):
        return None
    head = lemmas[-1]
    if any(t not in lx.PLACE_MODIFIERS and t != head and not index.knows(t) for t in lemmas):
        return None
    kinds = [e for e in index.entries if e.kind == "entity" and any(head in kind.split() for kind in e.types)]
    if len(kinds) < 2 or any(t != head and t not in lx.PLACE_MODIFIERS and
                             not all(t in e.tokens for e in kinds) for t in lemmas):
        return None  # one thing of its kind, or words that already tell which
    k = part_end if part_end is not None else j + 1
    while k < len(low) and low[k] in _LINKS:
        k += 1
    said, _ = words(k)
    landmark = index.match(phrase_lemmas(said)) if said else None
    if landmark is None or any(landmark.name == e.name for e in kinds):
        return None
    in_room = [e for e in kinds if e.zone == landmark.zone]
    if len(in_room) == 1:
        chosen = in_room[0]
    else:
        where = _point(index, landmark.name) if landmark.kind != "zone" else None
        if where is None or in_room:
            return None
        ranked = sorted(kinds, key=lambda e: math.dist(_point(index, e.name) or (math.inf, math.inf), where))
        chosen = ranked[0]
    return PlaceMatch(chosen.name, "entity", chosen.zone, 1.0, True)
