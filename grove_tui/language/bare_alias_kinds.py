"""A place matched only by a bare alias that is its head ("kiosk" of the phone kiosk), said with words
of another kind before the head: "the shoe repair kiosk", "the key-cutting kiosk" of a mall whose one
kiosk sells phones. The alias names the place when said alone; with a kind of its own before it, the
phrase names that kind, which must then agree with the place as any modifier must.
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.places import PlaceIndex, PlaceMatch


def by_bare_alias(index: PlaceIndex, match: PlaceMatch, lemmas: Sequence[str]) -> bool:
    """Whether an exact match holds only by an alias that is the phrase's head alone, with other words
    before the head: none of the place's longer names is in the phrase."""
    entry = index.entry(match.name)
    if entry is None or entry.kind == "zone" or len(lemmas) < 2 or (lemmas[-1],) not in entry.phrases:
        return False
    said = set(lemmas)
    return not any(len(p) > 1 and set(p) <= said for p in entry.phrases)
