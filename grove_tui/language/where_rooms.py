"""The room, not a thing in it, for a place said only by what people do there ("to where you hand your
coats in", "where they check your ID"): a headless "where" clause names a room by its function, and the
thing the clause handles (the coats, an ID) is often a fixture's one-word name there (the coat rails, called "coats"). When
the room holding that fixture says the clause's own words in its description or its names ("where coats
are checked in", "coat check"), and neither the fixture's own description nor the room's ("the PPE station where vests are kept")
says it of the fixture, the room is the place meant
(language/place_meaning.py, `where_clause`)."""

from __future__ import annotations

import re

from grove_tui.language.activity_rooms import _said_of
from grove_tui.language.place_described import _NOT_CONTENT
from grove_tui.language.places import PlaceIndex, PlaceMatch
from grove_tui.language.tokens import lemma, verb_lemma

Decided = tuple[PlaceMatch, float, str, tuple[str, ...]]


def _stems(text: str) -> set[str]:
    return {verb_lemma(lemma(w)) for w in re.findall(r"[a-z]+", text.lower()) if w not in _NOT_CONTENT}


def room_doing_where(index: PlaceIndex, activity: str, meant: Decided) -> Decided:
    """The room holding the fixture `meant` names when the room's description or names say a word of the
    clause `activity` and the fixture's own description says none; `meant` otherwise."""
    match = meant[0]
    if match.kind != "entity":
        return meant
    fixture, room = index.entry(match.name), index.entry(match.zone)
    if fixture is None or room is None or room.kind != "zone":
        return meant
    words = _stems(activity)
    if not any(len(name.split()) == 1 and _stems(name) <= words for name in fixture.said if _stems(name)):
        return meant  # the clause does not name the fixture as the thing handled ("photos" at the photo booth)
    said = _stems(room.description) | _stems(" ".join(room.said))
    if not words & said or words & _stems(fixture.description) or _said_of(fixture, room.description):
        return meant
    return (PlaceMatch(room.name, room.kind, room.name, match.score, False), meant[1],
            f"{meant[2]}; the room whose own words say it, {room.name}", meant[3])


def other_room_saying_it(index: PlaceIndex, activity: str, meant: Decided) -> Decided:
    """The one other room whose own description says every word of the clause `activity` ("where the
    dinghies are launched": the slipway "where dinghies ... are launched"), when the place `meant` is a
    fixture (the dinghy racks) in a room that does not say it all; `meant` otherwise. The
    thing handled is kept in one room and handled in another; the clause names where it is handled."""
    match = meant[0]
    if match.kind != "entity":
        return meant
    fixture, room = index.entry(match.name), index.entry(match.zone)
    if fixture is None or room is None:
        return meant
    words = _stems(activity)
    said_there = _loose(room.description) | _loose(" ".join(room.said)) | _loose(fixture.description)
    if len(words) < 2 or words <= said_there:
        return meant
    others = [e for e in index.entries if e.kind == "zone" and e.name != room.name and words <= _loose(e.description)]
    if len(others) != 1:
        return meant
    other = others[0]
    return (PlaceMatch(other.name, other.kind, other.name, match.score, False), meant[1],
            f"{meant[2]}; the room whose own words say all of it, {other.name}", meant[3])


def _loose(text: str) -> set[str]:
    """The stems of `text`, a past participle's also without its ending ("launched": "launch", "stored": "store")."""
    stems = _stems(text)
    return stems | {w[:-2] for w in stems if w.endswith("ed")} | {w[:-1] for w in stems if w.endswith("ed")}
