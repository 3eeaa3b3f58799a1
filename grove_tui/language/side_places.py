"""A place said as one "-side" word after people (round 52): "2 physios poolside", "three medics
pitchside", "a nurse bedside". The word is where they are, by the place its first half names; left as
one word it names no place and, in a list ("3 patients in the gym, 2 physios poolside"), the people
before it were lost. Before parsing, when the world knows the first half and the word ends a phrase
after a plural or counted person word, it is said "by the pool" (not when the world names the whole
word, as an ice rink's "rinkside": that word, and "-side" words read in place after the parse, are
bare_places.py's)."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.places import PlaceIndex

_SIDE = re.compile(r"(?<=[A-Za-z]s )(?P<place>[a-z]{3,})side\b(?=\s*(?:[,.;!?]|$|\band\b|\bwhile\b|\bwith\b))",
                   re.IGNORECASE)


def with_side_places(text: str, index: PlaceIndex) -> str:
    """The text with "<place>side" after people said "by the <place>" (module doc)."""
    def by(m: re.Match[str]) -> str:
        place = m.group("place")
        known = index.knows(place.lower()) and not index.knows(m.group(0).lower())  # "rinkside": a place itself
        return f"by the {place}" if known else m.group(0)
    return _SIDE.sub(by, text)
