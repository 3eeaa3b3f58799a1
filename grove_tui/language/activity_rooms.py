"""The room, not its fixture, for a place said only by what is done there ("to where their fingerprints
get scanned"): when the nearest name is a fixture's ("fingerprint scanners") but the description of the
room it stands in says the activity in its own words ("where applicants have their fingerprints
scanned") and the fixture's own description does not, the room is the place meant; a clause headed by a
kind of fixture ("the counter where you ...") keeps the fixture (language/place_meaning.py)."""

from __future__ import annotations

import re

from grove_tui.language.place_described import says_it
from grove_tui.language.places import MeaningMatch, PlaceEntry, PlaceIndex


def room_saying_it(index: PlaceIndex, best: MeaningMatch, activity: str) -> MeaningMatch | None:
    """The zone holding the fixture `best` when its description says `activity` and the fixture's does
    not; None otherwise."""
    if best.entry.kind == "zone":
        return None
    room = index.entry(best.entry.zone)
    if room is None or room.kind != "zone" or not says_it(activity, room.description) or \
            says_it(activity, best.entry.description) or _said_of(best.entry, room.description):
        return None
    return MeaningMatch(room, best.similarity, room.description)


def _said_of(fixture: PlaceEntry, description: str) -> bool:
    """Whether the room's description says its "where" of the fixture ("the PPE station where hi-vis
    vests are kept"): one of the fixture's names right before a "where"."""
    text = " ".join(re.findall(r"[a-z0-9]+", description.lower()))
    names = {" ".join(re.findall(r"[a-z0-9]+", name.lower())) for name in fixture.said}
    return any(name and f"{name} where" in text for name in names)
