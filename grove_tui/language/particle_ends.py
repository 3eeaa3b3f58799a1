"""Where a place said with a name that ends in a particle ends (round 33): "between goods in and the
dispatch bay", "from goods out, then the yard". The phrase reader stops before the particle ("in", "out"),
so the next place, said after "and" or "then", would not follow the place before; the name's own last
word is part of the phrase."""

from __future__ import annotations

from grove_tui.language.place_phrases import Place
from grove_tui.language.sentence import Sentence


def place_end(s: Sentence, place: Place) -> int:
    """The word index after the place phrase, with the particle that ends the place's name."""
    end = place.end
    if place.match is None or end >= s.n or end == 0:
        return end
    words = place.match.name.split("_")
    if len(words) >= 2 and s.low[end] == words[-1] and s.low[end - 1] == words[-2]:
        return end + 1  # "goods in": "in" is the name's, not a new phrase
    return end
