"""A generic word for the way into the building ("the entrance", "the entry", "the way in", "the entrance
doors", "the front door", "the building's entrance") means its public main entrance: the exit door
of a public entrance room called main or front, or that room, never a staff, service or side door
whose name only happens to hold "entrance" ("judges_entrance", "security_entry"). A word that says
which ("the judges' entrance", "the staff entrance", "the side entrance") leaves it to the words.
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.lexicon import BUILDING_WORDS
from grove_tui.language.places import PlaceEntry, PlaceIndex, PlaceMatch

Decided = tuple[PlaceMatch, float, str, tuple[str, ...]]

# The words a generic entrance phrase may hold, and no other.
_ENTRANCE = frozenset("entrance entry entryway way in front main door doors double glass public".split())
_SAYS_ENTRANCE = frozenset("entrance entry way".split())  # at least one of these ("the front door" too, below)
# A door of these words is no public main entrance, whatever else it is called.
_NOT_PUBLIC = frozenset("staff service goods delivery fire emergency private crew judge judges back kitchen "
                        "security side rear loading".split())
_DOOR = frozenset({"door", "doors"})


def generic_entrance(lemmas: Sequence[str], building: frozenset[str]) -> bool:
    """Whether a phrase is only a generic word for the way in ("the main entrance", "the way in",
    "the hotel entrance", "the front door"), with no word saying which entrance."""
    words = [t for t in lemmas if t not in building and t not in BUILDING_WORDS]
    if not words or not set(words) <= _ENTRANCE:
        return False
    return bool(set(words) & _SAYS_ENTRANCE) and words != ["way"] or words in (["front", "door"], ["front"])


def named_whole(index: PlaceIndex, lemmas: Sequence[str], match: PlaceMatch | None) -> bool:
    """Whether the words already name a place of the world by one of its own names, whole ("the front
    stables" of a riding school, whose name's "stables" is also a building word): that place, no
    generic way in."""
    entry = index.entry(match.name) if match is not None and match.exact else None
    content = tuple(t for t in lemmas if t not in ("the", "a", "an"))
    return entry is not None and len(content) > 1 and content in entry.phrases


def main_entrance(index: PlaceIndex, lemmas: Sequence[str], low: Sequence[str], j: int,
                  match: PlaceMatch | None = None) -> tuple[Decided, int] | None:
    """The public main entrance a generic entrance phrase (`lemmas`, ending before word j) means, and
    the index after the phrase ("the way in": the "in" too); None when the phrase says which entrance,
    the world has no public entrance door, or the words already read a public way in (`match`)."""
    if list(lemmas[-1:]) == ["way"]:
        if j >= len(low) or low[j] != "in":
            return None
        lemmas, j = (*lemmas, "in"), j + 1
    if not generic_entrance(lemmas, index.building_words) or named_whole(index, lemmas, match):
        return None
    door = _main_door(index)
    if door is None or (match is not None and _public_way_in(index, match, bool(set(lemmas) & _DOOR))):
        return None
    said = index.match(("entrance",))
    zone = index.entry(door.zone)
    if set(lemmas) & _DOOR:
        found = PlaceMatch(door.name, "door", door.zone, 1.0, True)
    elif said is not None and said.name in (door.name, door.zone):
        found = PlaceMatch(said.name, said.kind, said.zone, 1.0, True)  # what "the entrance" is, when it is this one
    elif zone is not None and "entrance" in zone.tag_tokens | zone.tokens:
        found = PlaceMatch(zone.name, "zone", zone.name, 1.0, True)
    else:
        found = PlaceMatch(door.name, "door", door.zone, 1.0, True)
    reason = f"'{' '.join(lemmas)}' says no entrance in particular: the public main entrance, {found.name}"
    return (found, 1.0, reason, ()), j


def _public_way_in(index: PlaceIndex, match: PlaceMatch, door: bool) -> bool:
    """Whether the words' own reading is a public way in: an exit door, or a room tagged as an entrance
    when no door was said, no word of which says staff, service, side or fire."""
    entry = index.entry(match.name)
    if entry is None or entry.tokens & _NOT_PUBLIC:
        return False
    return entry.exit or (not door and entry.kind == "zone" and "entrance" in entry.tag_tokens | entry.tokens)


def _main_door(index: PlaceIndex) -> PlaceEntry | None:
    """The public main entrance: an exit door no word of which says staff, service, side or fire, best
    one called main or front, in a room tagged as an entrance."""
    best: tuple[int, int, PlaceEntry] | None = None
    for order, e in enumerate(index.entries):
        if e.kind != "door" or not e.exit or e.tokens & _NOT_PUBLIC:
            continue
        zone = index.entry(e.zone)
        zone_words = (zone.tokens | zone.tag_tokens) if zone is not None else frozenset()
        if "staff" in zone_words or "private" in zone_words:
            continue
        rank = 2 * bool(e.tokens & {"main", "front"}) + 2 * bool("entrance" in zone_words) + \
            bool("entrance" in e.tokens)
        if rank and (best is None or rank > best[0]):
            best = (rank, -order, e)
    return best[2] if best is not None else None
