"""Fixtures people use, hold on to or look at, said with the room they are in (round 35).

"Hog the air hockey table in the arcade", "sketch the altarpiece in the old masters gallery", "man the
barrier in the car park": the room only says where the fixture is, and people stay at the fixture.
A chore done to things in a room ("polishes the tables in the restaurant") keeps the room
(worked_things.room_worked_in)."""

from __future__ import annotations

from grove_tui.language.tokens import verb_lemma

# Verbs whose object is a fixture people use, take up, keep watch on or look at, not a thing they work on.
USED_FIXTURE_VERBS = frozenset(
    "hog commandeer monopolise monopolize occupy use play man staff guard surround mob besiege swamp admire "
    "sketch draw photograph film study examine ogle eye queue ride try test copy".split())


def uses_fixture(verb: str) -> bool:
    """Whether `verb` ("hogs", "sketching", "man") takes a fixture people use or look at as its object."""
    low = verb.lower()
    return len(low) > 2 and not _bases(low).isdisjoint(USED_FIXTURE_VERBS)


def _bases(low: str) -> set[str]:
    """The base forms `low` may be inflected from, by its ending only: "manages" is no form of "man"."""
    bases = {verb_lemma(low), low}
    if low.endswith("ies"):
        bases.add(low[:-3] + "y")  # "copies"
    elif low.endswith("s"):
        bases |= {low[:-1], low[:-2]}  # "hogs", "sketches"
    for ending in ("ing", "ed"):
        if low.endswith(ending):
            stem = low[: -len(ending)]
            bases |= {stem, stem + "e", stem[:-1] + "y" if stem.endswith("i") else stem}  # "riding", "copied"
            if len(stem) > 2 and stem[-1] == stem[-2]:
                bases.add(stem[:-1])  # "manning", "hogged"
    return bases
