"""A place said with "its" after a room (round 50): "the travellers on platform one are moved out through
its emergency exit", "the guests in the ballroom leave by its side door". "its" stands for the room said
last before it, so the phrase is that room's door or fixture, even when other rooms have one alike (every
platform has an emergency exit). Without this, "its" was read as someone's own thing ("a film on her
phone") and the phrase, no whole name, was dropped."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.places import PlaceIndex, PlaceMatch

Decided = tuple[PlaceMatch, float, str, tuple[str, ...]]


def its_place(index: PlaceIndex, lemmas: Sequence[str], zones_before: Sequence[str]) -> Decided | None:
    """The door or fixture of the room said last before "its" (`zones_before`, in reading order) that the
    phrase names, when one of that room's places is among the phrase's best matches; module doc."""
    if not zones_before or not lemmas:
        return None
    zone = zones_before[-1]
    found = index.candidates(lemmas)
    if not found:
        return None
    best = found[0].score
    words = set(lemmas)
    mine = [m for m in found if m.zone == zone and m.kind != "zone" and (e := index.entry(m.name)) is not None
            and words <= e.tokens]  # "its fire exit": the room's own, though another's alias is "fire exit"
    if not mine:
        mine = [m for m in found if m.zone == zone and m.kind != "zone" and m.score >= best - 1e-6]
    if len(mine) != 1:
        return None
    return (mine[0], 0.9, f"'its {' '.join(lemmas)}': the {' '.join(lemmas)} of {zone}, said before", ())
