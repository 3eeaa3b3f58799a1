"""A thing of a room said with the room: "the robing room table", "the door of court 2", "the café's
till". The room's name decides which of the world's things of that kind is meant: the one in that
room (or, for a door, the one leading into it), when it is the only one."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.place_landmark import by_landmark
from grove_tui.language.owned_doors import door_of_owner
from grove_tui.language.places import MeaningMatch, PlaceIndex, PlaceMatch
from grove_tui.language.room_word_things import exit_of_room, own_word_thing, room_by_first_words, thing_said_inside
from grove_tui.language.room_word_things import exit_of_room_said as exit_of_room_said
from grove_tui.language.whole_names import said_whole
from grove_tui.language.tokens import lemma, phrase_lemmas


def _kind_words(index: PlaceIndex, name: str) -> frozenset[str]:
    entry = index.entry(name)
    if entry is None:
        return frozenset()
    return frozenset(w for kind in entry.types for w in kind.split()) | entry.tokens


def thing_of_zone(index: PlaceIndex, head: str, zone: str) -> PlaceMatch | None:
    """The one fixture of `zone` whose kind or name is `head` ("table" in the robing room), or the one
    door into it when `head` is a door word; None when the room has none or several."""
    zone_entry = index.entry(zone)
    if zone_entry is None or zone_entry.kind != "zone" or not head or head in lx.GENERIC_PLACE_HEADS:
        return None
    if head in zone_entry.tokens and head not in lx.DOOR_WORDS:
        return own_word_thing(index, head, zone)  # "the robing room": the room itself; "the dorm bunks": its bunks
    if head in ("door", "doorway", "entrance"):
        # the doors in the room and those of other rooms leading into it; several: the widest, the main door
        doors = [(d.width, z.name == zone, d.name, z.name) for z in index.world.zones for d in z.doors
                 if not d.exit and (d.leads_to == zone or z.name == zone)]
        best = max(((w, own) for w, own, _, _ in doors), default=None)
        main = [(name, z) for w, own, name, z in doors if (w, own) == best]
        return PlaceMatch(main[0][0], "door", main[0][1], 1.0, True) if len(main) == 1 else None
    if (out := exit_of_room(index, head, zone)) is not None:
        return out  # "the circle exit"
    things = [e for e in index.entries if e.kind == "entity" and e.zone == zone]
    found = [e for e in things if any(head in kind.split() for kind in e.types)] or \
        [e for e in things if head in _kind_words(index, e.name)]  # "the tables": the tables, not the "top table"
    if len(found) != 1:
        return None
    return PlaceMatch(found[0].name, "entity", found[0].zone, 1.0, True)


def zone_then_thing(index: PlaceIndex, lemmas: Sequence[str], match: PlaceMatch | None) -> PlaceMatch | None:
    """"the robing room table", "the restaurant counter": a room's whole name right before a kind of
    thing the room has (not a word of the room's own name) is that thing of the room, unless the
    phrase names a thing of its own that carries the room's word ("the court 1 bench")."""
    if len(lemmas) < 2 or said_whole(index, lemmas):
        return None
    head = lemmas[-1]
    before = tuple(lemmas[:-1])
    zones = [(len(p), e) for e in index.entries if e.kind == "zone" for p in e.phrases
             if len(p) <= len(before) and before[len(before) - len(p):] == p]
    if not zones and len(before) == 1:
        # "the banqueting tables": a word only one room is called by ("the banqueting suite"), then a kind
        # of thing it has; that room's thing, though another room's things are "the tables"
        called = [e for e in index.entries if before[0] in e.tokens]
        if len(called) == 1 and called[0].kind == "zone" and head not in called[0].tokens:
            return thing_of_zone(index, head, called[0].name)
    if not zones:
        return None
    zone = max(zones, key=lambda z: z[0])[1]
    if head in zone.tokens and (tuple(lemmas) in zone.phrases or own_word_thing(index, head, zone.name) is None) or (match is not None and match.kind != "zone" and match.zone == zone.name):
        return None
    said = index.entry(match.name) if match is not None and match.kind != "zone" else None
    if said is not None and any(t in zone.tokens for p in said.phrases for t in p if p and
                                 all(w in lemmas for w in p)):
        return None  # the thing's own name holds the room's word
    return thing_of_zone(index, head, zone.name)


def thing_of_named_zone(index: PlaceIndex, low: Sequence[str], lemmas: Sequence[str], j: int,
                        words: Callable[[int], tuple[list[str], int]],
                        preps: Sequence[str] = ("of", "in", "inside")) -> tuple[PlaceMatch, int] | None:
    """"the door of court 2", "the tables in the café": a kind of thing, then "of" (or "in") and a room
    the world names whole; the thing of that room and the index after the room's words."""
    if not lemmas or j + 1 >= len(low) or low[j] not in preps or len(lemmas) > 2:
        return None
    k = j + 1
    while k < len(low) and low[k] in lx.DETERMINERS:
        k += 1
    room, end = words(k)
    zone = index.match(phrase_lemmas(room)) if room else None
    if zone is None or zone.kind != "zone" or not zone.exact:
        return None
    whole = index.match(lemmas) if len(lemmas) > 1 else None
    if whole is not None and whole.exact and whole.zone == zone.name:
        return whole, end  # "the fire door in the Egyptian gallery": the one named whole, not its main door
    thing = thing_of_zone(index, lemmas[-1], zone.name)
    return (thing, end) if thing is not None else None


def thing_of_zone_said(index: PlaceIndex, low: Sequence[str], lemmas: Sequence[str], match: PlaceMatch | None,
                       j: int, words: Callable[[int], tuple[list[str], int]]
                       ) -> tuple[tuple[PlaceMatch, float, str, tuple[str, ...]], int] | None:
    """The thing of a room the phrase names with the room, decided, and the index after the phrase."""
    found = thing_of_named_zone(index, low, lemmas, j, words) or door_of_owner(index, low, lemmas, j) or \
        thing_said_inside(low, lemmas, j, lambda said, at: thing_of_named_zone(index, low, said, at, words))  # "the café's fire door"
    if found is None:
        thing = zone_then_thing(index, lemmas, match) or by_landmark(index, low, lemmas, j, words) or \
            (room_by_first_words(index, lemmas, low[j - 1] != lemmas[-1]) if (match is None or not match.exact) and j >= 1 else None)
        found = (thing, j) if thing is not None else None
    if found is None:
        return None
    thing, end = found
    reason = f"'{' '.join(low[i] for i in range(j - len(lemmas), end))}': the {lemmas[-1]} of {thing.zone}"
    return (thing, 1.0, reason, ()), end


def ones_of_zone(index: PlaceIndex, low: Sequence[str], k: int, said: Sequence[str],
                 words: Callable[[int], tuple[list[str], int]]) -> tuple[PlaceMatch, int] | None:
    """"(the benches in the waiting area, not) the ones in the corridor": "one(s)" standing for the
    thing said before (`said`, its words), of the room named after it; the thing and the index after."""
    before = [w for w in said[:next((i for i, w in enumerate(said) if w in lx.PLACE_PREPOSITIONS), len(said))]]
    if not before:
        return None
    head = lemma(before[-1])
    if k + 1 >= len(low) or low[k] not in ("one", "ones") or low[k + 1] not in ("in", "on", "at", "by", "of", "near"):
        return None
    return thing_of_named_zone(index, low, (head,), k + 1, words, ("in", "on", "at", "by", "of", "near"))


# How much less near a room's serving fixture may be than the room, for a purpose, and still be where it is done.
SERVED_MARGIN = 0.06


def served_at(index: PlaceIndex, ranked: Sequence[MeaningMatch], best: MeaningMatch) -> MeaningMatch:
    """"to get a coffee": where a room nearest a purpose serves it (the café's coffee counter, tagged
    for service or a queue), when that fixture is nearly as near as the room; else the room."""
    if best.entry.kind != "zone" or any("queue" in t for t in best.entry.types):
        return best  # a queue line is where the ride is queued for, not its boarding platform
    served = [r for r in ranked if r.entry.kind == "entity" and r.entry.zone == best.entry.name
              and r.similarity >= best.similarity - SERVED_MARGIN
              and {"service", "queue"} & (r.entry.tag_tokens | r.entry.tokens)]
    return served[0] if len(served) == 1 else best
