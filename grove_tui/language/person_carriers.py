"""What a person rides in while moved along is how they go, no place (round 56): "wheels the injured
player off the pitch and round to the dressing room in a wheelchair", "brings the toddler back to the
car in a buggy", "carries the fallen rider off the course on a stretcher". movers.carried_in reads such
a phrase only a few words after the verb of moving; here "in a"/"on a" and a noun of something a person
is carried or pushed in (a wheelchair, buggy, pram, stretcher) is no place wherever it falls in the
clause, unless the world has a place of that very name.
"""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence

# What a person rides in or on when someone else moves them (not a bed, chair or cot: one sits or lies there).
PERSON_CARRIERS = lx.CARRYING_THINGS - {"bed", "chair", "cot", "crib"}


def person_carrier(s: Sentence, at: int, lemmas: tuple[str, ...] | list[str]) -> bool:
    """Whether the phrase of "in"/"on" at `at` (lemmas, after "a"/"an") names what a person rides in (module doc)."""
    if not lemmas or lemmas[-1] not in PERSON_CARRIERS or s.low[at] not in ("in", "on"):
        return False
    found = s.index.match(tuple(lemmas))
    return found is None or not found.exact  # the world's own "stretcher" (a first-aid couch) is a place
