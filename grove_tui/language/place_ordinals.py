"""One of a series of alike places by its rank ("the second gate", "the last lift", "the third ward",
"the first seminar room"): the places the words after the ordinal name as their own kind, in the
order of their names (gate_a1, gate_a2, gate_b1, gate_b2; lift_1 < lift_2 < lift_3), the n-th of
them, or the last. An alias that says the rank ("first platform") is a name and wins before this is
asked; a rank past the end of the series ("the fifth lift" of three) chooses none. Read for
language/place_phrases.py."""

from __future__ import annotations

import re
from collections.abc import Sequence

from grove_tui.language.lexicon import DOOR_WORDS, GENERIC_PLACE_HEADS, PLACE_MODIFIERS
from grove_tui.language.places import PlaceEntry, PlaceIndex, PlaceMatch
from grove_tui.language.tokens import name_tokens

ORDINALS = {"first": 1, "1st": 1, "second": 2, "2nd": 2, "third": 3, "3rd": 3, "fourth": 4, "4th": 4,
            "fifth": 5, "5th": 5, "sixth": 6, "6th": 6, "last": -1, "final": -1}
# How sure a rank reads its place: the order of names is the world's, not always the one people see.
ORDINAL_SURE = 0.75
_IDENTIFIER = re.compile(r"[a-z]?\d+[a-z]?|[a-z]")


def ordinal_place(index: PlaceIndex, lemmas: Sequence[str]) -> tuple[PlaceMatch, float, str, tuple[str, ...]] | None:
    """The place "the <ordinal> <kind>" means, its confidence, the reason and no alternatives; None when
    the phrase has no rank, names a place outright, or its words name no series of two or more."""
    at = next((i for i, t in enumerate(lemmas) if t in ORDINALS), None)
    if at is None:
        return None
    content = [t for t in lemmas[at + 1:] if t and t not in PLACE_MODIFIERS]
    if not content or (len(content) == 1 and content[0] in GENERIC_PLACE_HEADS):
        return None  # "the last one", "the second room": no kind of place said
    whole = index.match(lemmas)
    if whole is not None and whole.exact and any(lemmas[at] in p for p in _entry_phrases(index, whole.name)):
        return None  # "the first platform": an alias says the rank
    head = content[-1]
    series: dict[frozenset[str], list[PlaceEntry]] = {}
    for e in index.entries:
        if (e.kind == "door" and head not in DOOR_WORDS) or not set(content) <= e.tokens:
            continue
        if head in _type_heads(e) or _own_head(e.name) == head:
            series.setdefault(e.types or frozenset({e.kind}), []).append(e)
    # only the places whose names number them are in an order ("meeting_room_1, _2", not the boardroom)
    groups = sorted(([e for e in g if any(_IDENTIFIER.fullmatch(t) for t in name_tokens(e.name)[1:])]
                     for g in series.values()), key=len, reverse=True)
    if not groups or len(groups[0]) < 2 or (len(groups) > 1 and len(groups[1]) == len(groups[0])):
        return None  # "the second lab" of the chemistry and robotics labs: no order said by their names
    if len({e.zone for e in groups[0]}) > 1 and any(e.kind != "zone" for e in groups[0]):
        return None  # "the third bed" of beds in every ward: which ward's is not said here
    ordered = sorted(groups[0], key=lambda e: (_natural(e.name), index.entries.index(e)))
    rank = ORDINALS[lemmas[at]]
    if rank > len(ordered):
        return None
    chosen = ordered[rank - 1] if rank > 0 else ordered[-1]
    said = " ".join([lemmas[at], *content])
    return (PlaceMatch(chosen.name, chosen.kind, chosen.zone, 1.0, True), ORDINAL_SURE,
            f"'{said}': {lemmas[at]} of {', '.join(e.name for e in ordered[:4])}{', ...' if len(ordered) > 4 else ''}", ())


def _entry_phrases(index: PlaceIndex, name: str) -> tuple[tuple[str, ...], ...]:
    entry = index.entry(name)
    return entry.phrases if entry is not None else ()


def _type_heads(entry: PlaceEntry) -> set[str]:
    """The head word of a place's type ("desk" of "gate desk", "room" of "exam room")."""
    return {words[-1] for text in entry.types if (words := name_tokens(text))}


def _own_head(name: str) -> str:
    """The last word of a name that is no identifier ("gate" of gate_a1, "bed" of ward_a_bed_1)."""
    words = [t for t in name_tokens(name) if not _IDENTIFIER.fullmatch(t)]
    return words[-1] if words else ""


def _natural(name: str) -> tuple[tuple[int, str], ...]:
    """A name's sort key with its numbers read as numbers (room_9 before room_10)."""
    return tuple((int(part), "") if part.isdigit() else (0, part) for part in re.split(r"(\d+)", name) if part)


def series_number_at(index: PlaceIndex, words: Sequence[str]) -> bool:
    """Whether the words start with the name of a numbered series of the world and a number ("lecture
    theatre 3" where there are lecture theatres 1 and 2, "platform 9"): one of its places, or one the
    world lacks, but a place either way ("to lecture theatre 3" is where they go, not what they do, though
    the parser makes "lecture" a verb)."""
    lemmas = [t for w in words[:5] for t in name_tokens(w)]
    at = next((m for m, t in enumerate(lemmas) if m > 0 and any(ch.isdigit() for ch in t)
               and _IDENTIFIER.fullmatch(t)), None)
    if at is None:
        return False
    kind = tuple(lemmas[:at])
    return any(len(p) == at + 1 and p[:-1] == kind and _IDENTIFIER.fullmatch(p[-1]) for e in index.entries
               for p in e.phrases)
