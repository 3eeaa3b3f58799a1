"""A scale word alone as a rough count (round 32): "the hundred-odd travellers on it", "the thousand or so
fans", "some hundred-odd shoppers". A scale word needs "a" or a number before it to be read as a number
("a hundred", "two hundred"); after "the" or "some" it was read as no number at all, and the group's
count was a guess. Written as its figure ("the 100-odd travellers"), the rough count is read like
"the thirty-odd": about a hundred."""

from __future__ import annotations

import re

_SCALES = {"hundred": "100", "thousand": "1000"}
_ROUGH = re.compile(r"\b(the|some|another|these|those)\s+(hundred|thousand)(?=\s*-\s*odd\b|\s+odd\b|\s+or\s+so\b"
                    r"|\s+or\s+thereabouts\b)", re.IGNORECASE)


def with_scale_figures(text: str) -> str:
    """The text with a scale word alone before "-odd" or "or so" written as its figure (module doc)."""
    return _ROUGH.sub(lambda m: f"{m.group(1)} {_SCALES[m.group(2).lower()]}", text)
