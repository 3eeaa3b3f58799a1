"""A numbered thing inside a zone, named by its number, is that thing (round 50): "after their doubles
on court 6, ... walk back to the bar", "done with bay 3, the fitters ...". A fixture said in a scene
clause before the subject is usually only where the scene is, and the group starts in its room ("smoke
pours from the star projector and the audience flee"); but a fixture whose own name carries a number,
said with that number, is one of a series of places people are on or at (courts, bays, lanes, pitches),
and that numbered place is where they start."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.places import PlaceIndex, PlaceMatch
from grove_tui.language.tokens import phrase_lemmas


def named_by_number(index: PlaceIndex, match: PlaceMatch, words: Sequence[str]) -> bool:
    """Whether `match` is a fixture named by its number and the phrase `words` says that number."""
    if match.kind != "entity":
        return False
    entry = index.entry(match.name)
    if entry is None:
        return False
    numbers = {t for t in entry.tokens if any(ch.isdigit() for ch in t)}
    said = set(phrase_lemmas(tuple(w.lower() for w in words)))
    return bool(numbers & said)
