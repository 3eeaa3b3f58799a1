"""A single thing is not a place named as many (issue 29): "the supermarket" of an outlet village is
near "the shops", the avenue's plural name for its row of shops, by meaning (0.70), and a rescue by
meaning read it as the avenue. A place named in the plural ("the shops", "restaurants") is a collection
of things of a kind; a phrase in the singular whose nearest name is such a plural names one thing the
world lacks, and is refused rather than rescued. "the stores" (plural) is still rescued as the store
room, and a singular name the world has is never in question here (it matches by its words)."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.places import PlaceIndex
from grove_tui.language.tokens import lemma


def _plural(word: str) -> bool:
    return word.isalpha() and lemma(word) != word


def singular_near_plural(index: PlaceIndex, phrase: Sequence[str], name: str) -> bool:
    """Whether the singular phrase's nearest name of the place `name` is a plural one (module doc)."""
    words = [w for w in phrase if w.isalpha()]
    if not words or _plural(words[-1].lower()):
        return False
    near = index.by_meaning(" ".join(phrase), among={name})
    if not near:
        return False
    said = near[0].nearest.lower().split()
    return bool(said) and _plural(said[-1])
