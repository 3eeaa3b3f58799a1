"""A place tallied in chat (issue 29): "conference rm x3, 4 coders at their desks", "kitchen x2", "waiting
area ×5": so many people at that place, as "3 people in conference rm". Read as it stands, "x3" is no
count and the place names nobody, so the people there are lost. Only when the words before the tally
name a place of the world, so "coffee x2" in a list of orders is left alone where the world has no
such place."""

from __future__ import annotations

import re

from grove_tui.language.places import PlaceIndex
from grove_tui.language.purposed_places import place_named

_TALLY = re.compile(r"(^|[,;:]\s*|\n\s*)([A-Za-z][A-Za-z' -]{1,40}?)\s+[x×X]\s?(\d{1,3})\b(?=\s*(?:[,;.!]|$|\n))")
_CHAT_WORDS = {"rm": "room", "rms": "rooms", "mtg": "meeting"}


def with_chat_place_tallies(text: str, index: PlaceIndex) -> str:
    """The text with "<place> xN" said as "N people in <place>" (module doc)."""

    def tally(m: re.Match[str]) -> str:
        words = [_CHAT_WORDS.get(w.lower(), w) for w in m.group(2).split()]
        if int(m.group(3)) < 1 or place_named(index, words) is None:
            return m.group(0)
        return f"{m.group(1)}{m.group(3)} people in {m.group(2)}"

    return _TALLY.sub(tally, text)
