"""A word for the building before a place's head ("the hospital canteen", "the clinic kitchen", round 51).

Such a word says which building the place is in, not what kind of place it is; read by meaning it
brings the phrase near any place named after the building's staff or purpose ("hospital canteen" is
0.62 from "nurses station", "canteen" alone 0.49), and so rescues a place the world lacks from being
refused. A phrase about to be refused is read by meaning without it; the head is kept whatever it is
("the staff area")."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.places import PlaceIndex


def of_no_building(index: PlaceIndex, phrase: Sequence[str], lemmas: Sequence[str]) -> tuple[list[str], list[str]]:
    """The phrase and its lemmas without the building words before their last word."""
    building = index.building_words
    kept_phrase = [w for w in phrase[:-1] if w not in building] + list(phrase[-1:])
    kept_lemmas = [w for w in lemmas[:-1] if w not in building] + list(lemmas[-1:])
    return kept_phrase, kept_lemmas
