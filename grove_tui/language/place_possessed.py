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
