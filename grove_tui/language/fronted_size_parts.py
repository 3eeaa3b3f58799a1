"""A fronted whole's part said with a word for a group of a size (round 29): "Of the twelve folk in
the waiting area, a trio are called through", "Out of the ten at the bar, a foursome head off". The
reader took "a trio" for a group of its own beside the whole; it is so many of them, and is written
out as the number ("three of them") before the sentence is parsed, so the whole and its part are read
as any "Of the twelve nurses on the ward, three go ..."."""

from __future__ import annotations

import re

_SIZES = {"duo": "two", "twosome": "two", "trio": "three", "threesome": "three", "quartet": "four",
          "foursome": "four", "quintet": "five", "fivesome": "five", "sextet": "six"}
_FRONTED = re.compile(r"(?:^|(?<=[.;!?:])\s+|(?<=,)\s+(?:and|but|then|so)\s+)"
                      r"(?:[Oo]ut )?[Oo]f (?:the|those|these|all)\s+[^,.;!?]{1,80},\s+")
_PART = re.compile(r"an?\s+(" + "|".join(_SIZES) + r")\b(?!\s+of\b)", re.IGNORECASE)


def with_fronted_size_parts(text: str) -> str:
    """The text with a fronted whole's part "a trio" written "three of them" (see the module doc)."""
    out: list[str] = []
    at = 0
    for m in _FRONTED.finditer(text):
        part = _PART.match(text, m.end())
        if part is None:
            continue
        out.append(text[at:part.start()] + _SIZES[part.group(1).lower()] + " of them")
        at = part.end()
    out.append(text[at:])
    return "".join(out)
