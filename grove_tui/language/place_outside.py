""""outside the pharmacy", "just outside the café", "in front of the bookshop" (round 18): where people
stand is the zone the room's door opens to, not the room; "inside the pharmacy" is the room. A thing
or a door said after "outside" stays what it is, and a room whose only doors lead out of the
building stays itself (there is no zone of the world just outside it)."""

from __future__ import annotations

from grove_tui.language.bound_for import bound_zone
from grove_tui.language.place_queues import queue_zone_for
from grove_tui.language.places import PlaceIndex, PlaceMatch
from grove_tui.language.sentence import Sentence


def _outside_said(s: Sentence, at: int) -> bool:
    if s.low[at] == "outside":
        return at + 1 >= s.n or s.low[at + 1] != "of" or at + 2 < s.n  # "outside (of) the pharmacy"
    return tuple(s.low[at:at + 3]) == ("in", "front", "of")


def zone_outside(index: PlaceIndex, zone: str) -> str | None:
    """The zone the room's widest door opens to (its own doors, then other rooms' doors into it)."""
    doors: list[tuple[float, bool, str]] = [
        (float(d.width), z.name == zone, str(d.leads_to if z.name == zone else z.name))
        for z in index.world.zones for d in z.doors
        if not d.exit and (d.leads_to == zone or z.name == zone) and (d.leads_to if z.name == zone else z.name)]
    doors = [d for d in doors if d[2] != zone]
    if not doors:
        return None
    return max(doors)[2]


def outside_zone(s: Sentence, at: int, match: PlaceMatch) -> tuple[PlaceMatch, str] | None:
    """The zone just outside the room `match` when the phrase at `at` says "outside" or "in front of"
    it, with the reason; None otherwise."""
    if match.kind != "zone" or not _outside_said(s, at):
        return None
    out = zone_outside(s.index, match.name)
    entry = s.index.entry(out) if out is not None else None
    if entry is None:
        return None
    return (PlaceMatch(entry.name, "zone", entry.name, match.score, match.exact),
            f"outside {match.name}: {entry.name}, the zone its door opens to")


def zone_around(s: Sentence, at: int, end: int, match: PlaceMatch) -> tuple[PlaceMatch, str] | None:
    """The zone people are in when the phrase at `at` (to `end`) names `match` but means the zone
    outside it or the queue for it; None when it means `match`."""
    return outside_zone(s, at, match) or queue_zone_for(s, at, end, match) or bound_zone(s, at, match)
