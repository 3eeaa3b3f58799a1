"""Places named by a tier or storey of a building (round 35): "the upper circle", "the dress circle",
"the first floor", "the top floor". Alone the head names no place ("a circle of friends", "sit on the
floor", the building's floor); with the word that says which tier or storey it is, the phrase names a
kind of place, and a world with no place so called refuses it rather than read nothing."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.places import PlaceIndex

# The heads, each with the words before it that make a tier or storey of it.
_TIERS: dict[str, frozenset[str]] = {
    "circle": frozenset("upper dress dressing grand royal family lower".split()),  # "dress" may come lemmatised as "dressing"
    "floor": frozenset("ground first second third fourth fifth top upper lower basement mezzanine".split()),
}


def tier_place(lemmas: Sequence[str]) -> str | None:
    """The tier or storey a phrase ends with ("upper circle" of "the upper circle"), or None."""
    words = [t for t in lemmas if t]
    if len(words) < 2 or words[-1] not in _TIERS or words[-2] not in _TIERS[words[-1]]:
        return None
    if len(words) >= 3 and words[-2] == "ground" and words[-3] in ("lower", "upper"):
        return " ".join(words[-3:])  # "the lower ground floor"
    return " ".join(words[-2:])


def absent_tier(index: PlaceIndex, lemmas: Sequence[str]) -> str | None:
    """The tier or storey a phrase names when no place of the world is called by it, or None."""
    said = tier_place(lemmas)
    if said is None:
        return None
    wanted = tuple(said.split())
    for e in index.entries:
        for p in e.phrases:
            if any(tuple(p[i:i + len(wanted)]) == wanted for i in range(len(p) - len(wanted) + 1)):
                return None
    return said
