"""A place whose name is a list, written with its commas (round 44): "stroll through to births, deaths and
marriages", "head for the timber, sheet materials and paint", where the world's name is "births deaths and
marriages". Read at its first comma, the name was cut short ("births": a place the world lacks) and the
group lost where it goes. A run of words that is one of the world's names but for commas between them is
written as the name."""

from __future__ import annotations

import re
from functools import lru_cache
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.places import PlaceIndex


@lru_cache(maxsize=64)
def _patterns(names: tuple[str, ...]) -> tuple[tuple[re.Pattern[str], str], ...]:
    out = []
    for name in names:
        words = name.split()
        if len(words) < 3 or "and" not in words[1:]:
            continue
        joints = [r"\s+" if words[k] == "and" else r",?\s+" for k in range(len(words) - 1)]
        pattern = r"\b" + "".join(re.escape(w) + j for w, j in zip(words, joints)) + re.escape(words[-1]) + r"\b"
        out.append((re.compile(pattern, re.IGNORECASE), name))
    return tuple(out)


def with_listed_place_names(text: str, index: PlaceIndex) -> str:
    """The text with a place's name said with commas between its words written as the name (module doc)."""
    if "," not in text:
        return text
    names = tuple(sorted({said.lower() for e in index.entries for said in e.said if " and " in said}))
    for pattern, name in _patterns(names):
        text = pattern.sub(name, text)
    return text
