"""Which of a person's places a possessive room name means: "the manager's office", "the nurses'
station", "the teachers' lounge". A room of theirs whose own name or alias carries the head is that room,
before any thing inside one of their rooms that shares the head ("office" of the office safe); only when
no room of theirs is called so is the head a thing in one of their rooms ("the parents' bed": the bed of
their bedroom, not the bedroom)."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.places import PlaceEntry


def owned_places(entries: Sequence[PlaceEntry], theirs: Sequence[PlaceEntry], head: str) -> list[PlaceEntry]:
    """The places of `theirs` (the person's own, from the index) that a phrase headed `head` may name,
    best first: their room called so, else a thing in a room of theirs, else any place of theirs."""
    rooms = {e.name for e in theirs if e.kind == "zone"}
    # a generic head ("room") names no room in particular: left to the last tier, as before
    called = [e for e in theirs if e.kind == "zone" and head in e.tokens and head not in lx.GENERIC_PLACE_HEADS]
    if called:
        return called
    inside = [e for e in entries if e.kind not in ("zone", "door") and e.zone in rooms
              and head in e.tokens and head not in lx.GENERIC_PLACE_HEADS]
    return inside or [e for e in theirs if (head in e.tokens or (head in lx.GENERIC_PLACE_HEADS and e.kind == "zone"))
                      and (e.kind != "door" or head in lx.DOOR_WORDS)]  # "her ward" is no door of her station


# Kinds of room a person sleeps or stays in, their own room of "her room", "their rooms" (round 71).
_OWN_ROOM_TYPES = frozenset("bedroom guest_room suite dormitory dorm cabin".split())
# Kinds of room that are shared by everyone of a kind, never one person's own ("the residents' lounge").
_SHARED_TYPES = frozenset("lounge living_room day_room common_room sitting_room".split())


def own_rooms(entries: Sequence[PlaceEntry], owned: Sequence[PlaceEntry], lemmas: Sequence[str]) -> list[PlaceEntry]:
    """A person's own room said with a possessive and one word ("her room", "their rooms", "their dorm"), where the
    world has rooms people sleep or stay in (a care home's bedrooms, a hotel's guest rooms): those of
    theirs, else all of them, when no room of theirs by kind (`owned`) is more than a shared lounge."""
    content = [t for t in lemmas if t not in lx.PLACE_MODIFIERS]
    if len(content) != 1 or any(e.kind == "zone" and not {t.replace(" ", "_") for t in e.types} & _SHARED_TYPES
                                   for e in owned):
        return []
    rooms = [e for e in entries if e.kind == "zone" and {t.replace(" ", "_") for t in e.types} & _OWN_ROOM_TYPES
             and (content[0] == "room" or content[0] in e.tokens)]  # "their dorm": the dorms
    return [e for e in rooms if e in owned] or rooms
