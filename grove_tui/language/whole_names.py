"""A place's whole name said exactly: "the stage door" is the room the world calls "stage door", not
the door of the stage, and "the hall entrance" the porch so called, not an opening of the hall. When
the words are all of one place's own name or alias, no reading of them as a thing of another room
(a room's name, then a kind of thing) may replace it."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.places import PlaceIndex


def said_whole(index: PlaceIndex, lemmas: Sequence[str]) -> bool:
    """Whether the lemmatised words are, whole, one place's name or alias."""
    said = tuple(lemmas)
    return any(said in e.phrases for e in index.entries)
